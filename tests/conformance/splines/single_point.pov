#version 3.7;
#declare S = spline { linear_spline 0, <1,2,3> }
#debug concat("S(0) = <", vstr(3, S(0), ", ", 0, 1), ">\n")
#debug concat("S(5) = <", vstr(3, S(5), ", ", 0, 1), ">\n")
