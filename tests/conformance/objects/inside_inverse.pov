#version 3.7;
#declare S = sphere { 0, 1 inverse }
#debug concat("inside(S, <0, 0, 0>) = ", str(inside(S, <0, 0, 0>), 0, 0), "\n")
#debug concat("inside(S, <2, 0, 0>) = ", str(inside(S, <2, 0, 0>), 0, 0), "\n")
