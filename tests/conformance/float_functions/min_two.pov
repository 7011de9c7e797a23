#version 3.7;
#debug concat("min(3,1) = ", str(min(3,1), 0, 3), "\n")
#debug concat("min(-1,-2) = ", str(min(-1,-2), 0, 3), "\n")
#debug concat("min(5,5) = ", str(min(5,5), 0, 3), "\n")
