#version 3.7;
#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#debug concat("C.x = ", str(C.x, 0, 3), "\n")
#debug concat("C.y = ", str(C.y, 0, 3), "\n")
#debug concat("C.z = ", str(C.z, 0, 3), "\n")
#debug concat("C.t = ", str(C.t, 0, 3), "\n")
