#version 3.7;
#declare F = function { pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } }
#debug concat("F(0.25, 0, 0) = <", vstr(5, F(0.25, 0, 0), ", ", 0, 6), ">\n")
#debug concat("F(0.75, 0, 0).blue = ", str(F(0.75, 0, 0).blue, 0, 6), "\n")
#debug concat("F(0.75, 0, 0).gray = ", str(F(0.75, 0, 0).gray, 0, 6), "\n")
