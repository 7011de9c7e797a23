#version 3.7;
#declare A = spline { linear_spline 0, <0,0,0> 1, <1,2,0> 2, <2,0,0> 3, <3,3,0> }
#declare B = spline { A cubic_spline }
#debug concat("B(1.5) = <", vstr(3, B(1.5), ", ", 0, 6), ">\n")
#debug concat("A(1.5) = <", vstr(3, A(1.5), ", ", 0, 6), ">\n")
