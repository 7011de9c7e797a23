#version 3.7;
#debug concat("vdot(<1,2,3>, <4,5,6>) = ", str(vdot(<1,2,3>, <4,5,6>), 0, 6), "\n")
#debug concat("vdot(x, y) = ", str(vdot(x, y), 0, 6), "\n")
#debug concat("vdot(<1,1,1>, <-1,-1,-1>) = ", str(vdot(<1,1,1>, <-1,-1,-1>), 0, 6), "\n")
