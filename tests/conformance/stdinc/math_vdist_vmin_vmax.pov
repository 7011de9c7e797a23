#version 3.7;
#include "math.inc"
#debug concat("VDist(<1, 2, 3>, <4, 6, 3>) = ", str(VDist(<1, 2, 3>, <4, 6, 3>), 0, 6), "\n")
#debug concat("VMin(<3, -1, 2>) = ", str(VMin(<3, -1, 2>), 0, 3), "\n")
#debug concat("VMax(<3, -1, 2>) = ", str(VMax(<3, -1, 2>), 0, 3), "\n")
