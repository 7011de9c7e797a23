#version 3.7;
#declare Base = rgb <0.1, 0.2, 0.3>;
#declare C = color Base + red 0.5;
#debug concat("C = <", vstr(5, C, ", ", 0, 2), ">\n")
