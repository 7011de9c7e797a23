#version 3.7;
#declare A = spline { linear_spline 0, <0,0,0> 1, <1,1,1> }
#declare B = spline { A 2, <3,3,3> }
#debug concat("B(1.5) = <", vstr(3, B(1.5), ", ", 0, 3), ">\n")
#debug concat("A(1.5) = <", vstr(3, A(1.5), ", ", 0, 3), ">\n")
