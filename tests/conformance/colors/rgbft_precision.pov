#version 3.7;
#declare C = rgbft <0.1, 0.2, 0.3, 0.7, 0.9>;
#debug concat("C.red = ", str(C.red, 0, 12), "\n")
#debug concat("C.filter = ", str(C.filter, 0, 12), "\n")
#debug concat("C.transmit = ", str(C.transmit, 0, 12), "\n")
