#version 3.7;
#declare I = intersection { sphere { 0, 1 } plane { x, 0 } }
#debug concat("inside(I, <-0.5, 0, 0>) = ", str(inside(I, <-0.5, 0, 0>), 0, 0), "\n")
#debug concat("inside(I, <0.5, 0, 0>) = ", str(inside(I, <0.5, 0, 0>), 0, 0), "\n")
