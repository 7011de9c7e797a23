#version 3.7;
#declare C = rgb <0.5, 0.5, 0.5> transmit 0.25;
#debug concat("C = <", vstr(5, C, ", ", 0, 2), ">\n")
