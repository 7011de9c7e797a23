#version 3.7;
#declare F = function { spline { linear_spline 0, <0,0,0,0,0> 1, <1,2,3,4,5> } }
#debug concat("F(0.5) = <", vstr(5, F(0.5), ", ", 0, 3), ">\n")
