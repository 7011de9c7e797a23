#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = srgbf <0.5, 0.5, 0.5, 0.5>;
#declare B = srgbt <0.2, 0.3, 0.4, 0.5>;
#debug concat("A = <", vstr(5, A, ", ", 0, 6), ">\n")
#debug concat("B = <", vstr(5, B, ", ", 0, 6), ">\n")
