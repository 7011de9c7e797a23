#version 3.7;
#declare F = function { transform { translate <1, 2, 3> scale 2 inverse } }
#debug concat("F(0, 0, 0) = <", vstr(3, F(0, 0, 0), ", ", 0, 3), ">\n")
