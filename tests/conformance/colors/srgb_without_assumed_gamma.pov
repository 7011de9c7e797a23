#version 3.7;
#debug "before\n"
#declare C = srgb <0.5, 0.5, 0.5>;
#debug concat("C = <", vstr(5, C, ", ", 0, 3), ">\n")
