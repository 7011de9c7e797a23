#version 3.7;
#declare C = rgb <0.1, 0.2, 0.3>;
#debug concat("C.red = ", str(C.red, 0, 12), "\n")
#debug concat("C.green = ", str(C.green, 0, 12), "\n")
#debug concat("C.blue = ", str(C.blue, 0, 12), "\n")
