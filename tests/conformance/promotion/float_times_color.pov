#version 3.7;
#declare C = rgb <1, 0.5, 0.25> * 2;
#debug concat("C = <", vstr(5, C, ", ", 0, 3), ">\n")
