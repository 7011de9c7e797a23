#version 3.7;
#debug concat("max(3,1) = ", str(max(3,1), 0, 3), "\n")
#debug concat("max(-1,-2) = ", str(max(-1,-2), 0, 3), "\n")
#debug concat("max(5,5) = ", str(max(5,5), 0, 3), "\n")
