#version 3.7;
#declare D = difference { sphere { 0, 2 } sphere { 0, 1 } }
#debug concat("inside(D, <0, 0, 0>) = ", str(inside(D, <0, 0, 0>), 0, 0), "\n")
#debug concat("inside(D, <1.5, 0, 0>) = ", str(inside(D, <1.5, 0, 0>), 0, 0), "\n")
#debug concat("inside(D, <3, 0, 0>) = ", str(inside(D, <3, 0, 0>), 0, 0), "\n")
