#version 3.7;
#declare S = sphere { 0, 1 }
#debug concat("inside(S, <0, 0, 0>) = ", str(inside(S, <0, 0, 0>), 0, 0), "\n")
#debug concat("inside(S, <2, 0, 0>) = ", str(inside(S, <2, 0, 0>), 0, 0), "\n")
#debug concat("inside(S, <0.5, 0.5, 0.5>) = ", str(inside(S, <0.5, 0.5, 0.5>), 0, 0), "\n")
