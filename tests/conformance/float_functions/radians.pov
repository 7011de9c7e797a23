#version 3.7;
#debug concat("radians(180) = ", str(radians(180), 0, 9), "\n")
#debug concat("radians(1) = ", str(radians(1), 0, 9), "\n")
#debug concat("radians(-45) = ", str(radians(-45), 0, 9), "\n")
