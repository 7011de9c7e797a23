#version 3.7;
#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#debug concat("C.red = ", str(C.red, 0, 3), "\n")
#debug concat("C.green = ", str(C.green, 0, 3), "\n")
#debug concat("C.blue = ", str(C.blue, 0, 3), "\n")
#debug concat("C.filter = ", str(C.filter, 0, 3), "\n")
#debug concat("C.transmit = ", str(C.transmit, 0, 3), "\n")
