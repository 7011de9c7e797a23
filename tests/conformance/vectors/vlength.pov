#version 3.7;
#debug concat("vlength(<3,4,0>) = ", str(vlength(<3,4,0>), 0, 9), "\n")
#debug concat("vlength(<1,1,1>) = ", str(vlength(<1,1,1>), 0, 9), "\n")
#debug concat("vlength(0) = ", str(vlength(0), 0, 9), "\n")
#debug concat("vlength(<1,2>) = ", str(vlength(<1,2>), 0, 9), "\n")
