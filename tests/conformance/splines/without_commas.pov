#version 3.7;
#declare S = spline { linear_spline 0 <0,0,0> 1 <2,4,6> }
#debug concat("S(0.25) = <", vstr(3, S(0.25), ", ", 0, 3), ">\n")
