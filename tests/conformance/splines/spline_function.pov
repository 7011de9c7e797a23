#version 3.7;
#declare F = function { spline { linear_spline 0.0, <0,0,0> 0.5, <1,0,0> 1.0, <0,0,0> } }
#debug concat("F(0.7) = <", vstr(3, F(0.7), ", ", 0, 6), ">\n")
#debug concat("F(0.25) = <", vstr(3, F(0.25), ", ", 0, 6), ">\n")
