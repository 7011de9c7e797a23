#version 3.7;
#declare Pl = plane { y, 0 }
#debug concat("inside(Pl, <0, -1, 0>) = ", str(inside(Pl, <0, -1, 0>), 0, 0), "\n")
#debug concat("inside(Pl, <0, 1, 0>) = ", str(inside(Pl, <0, 1, 0>), 0, 0), "\n")
