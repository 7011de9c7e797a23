#version 3.7;
#declare F = function { pigment { color rgbft <0.1, 0.2, 0.3, 0.4, 0.5> } }
#debug concat("F(1, 2, 3) = <", vstr(5, F(1, 2, 3), ", ", 0, 9), ">\n")
