#version 3.7;
#declare A = <1,2,3> + <1,1,1,1>;
#debug concat("A = <", vstr(5, A, ", ", 0, 1), ">\n")
