#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare C = srgbt <0.1, 0.7, 1, 0.3>;
#debug concat("C.red = ", str(C.red, 0, 12), "\n")
#debug concat("C.green = ", str(C.green, 0, 12), "\n")
#debug concat("C.blue = ", str(C.blue, 0, 12), "\n")
#debug concat("C.transmit = ", str(C.transmit, 0, 12), "\n")
