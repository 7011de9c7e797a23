#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare C = srgbft <0.04, 0.5, 0.9, 0.1, 0.2>;
#debug concat("C = <", vstr(5, C, ", ", 0, 9), ">\n")
