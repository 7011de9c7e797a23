#version 3.7;
#debug concat("int(2.7) = ", str(int(2.7), 0, 3), "\n")
#debug concat("int(2) = ", str(int(2), 0, 3), "\n")
#debug concat("int(0.999) = ", str(int(0.999), 0, 3), "\n")
#debug concat("int(1e9+0.5) = ", str(int(1e9+0.5), 0, 3), "\n")
