#version 3.7;
#declare F = function { transform { translate <1, 2, 3> } }
#debug concat("F(0, 0, 0) = <", vstr(3, F(0, 0, 0), ", ", 0, 3), ">\n")
#debug concat("F(1, 1, 1) = <", vstr(3, F(1, 1, 1), ", ", 0, 3), ">\n")
