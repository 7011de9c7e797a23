#version 3.7;
#declare B = box { -1, 1 }
#debug concat("inside(B, <0.9, -0.9, 0>) = ", str(inside(B, <0.9, -0.9, 0>), 0, 0), "\n")
#debug concat("inside(B, <1.1, 0, 0>) = ", str(inside(B, <1.1, 0, 0>), 0, 0), "\n")
