#version 3.7;
#debug "before\n"
#declare x = <2,0,0>;
#debug concat("x = <", vstr(3, x, ", ", 0, 6), ">\n")
