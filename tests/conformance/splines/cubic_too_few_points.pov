#version 3.7;
#declare S = spline { cubic_spline 0, <0,0,0> 1, <1,1,1> 2, <2,0,0> }
#debug concat("S(1) = <", vstr(3, S(1), ", ", 0, 3), ">\n")
#debug concat("S(0.5) = <", vstr(3, S(0.5), ", ", 0, 3), ">\n")
