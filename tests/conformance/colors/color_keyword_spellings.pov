#version 3.7;
#declare A = color rgb <1,0,0>;
#declare B = colour rgb <0,1,0>;
#debug concat("A+B = <", vstr(5, A+B, ", ", 0, 1), ">\n")
