#version 3.7;
#declare S = spline { linear_spline 0, <0,0,0> 1, <2,4,6> }
#debug concat("S(0.5).y = ", str(S(0.5).y, 0, 3), "\n")
