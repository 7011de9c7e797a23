#version 3.7;
#debug concat("floor(1.8) = ", str(floor(1.8), 0, 3), "\n")
#debug concat("floor(-1.2) = ", str(floor(-1.2), 0, 3), "\n")
#debug concat("floor(2) = ", str(floor(2), 0, 3), "\n")
#debug concat("floor(-0.5) = ", str(floor(-0.5), 0, 3), "\n")
#debug concat("floor(-0.0000001) = ", str(floor(-0.0000001), 0, 3), "\n")
