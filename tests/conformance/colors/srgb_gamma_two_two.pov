#version 3.7;
global_settings { assumed_gamma 2.2 }
#declare C = srgb <0.5, 0.2, 1>;
#debug concat("C = <", vstr(5, C, ", ", 0, 9), ">\n")
