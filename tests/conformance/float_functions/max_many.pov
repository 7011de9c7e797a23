#version 3.7;
#debug concat("max(3,1,2) = ", str(max(3,1,2), 0, 3), "\n")
#debug concat("max(-5,-4,-3,-2,-1) = ", str(max(-5,-4,-3,-2,-1), 0, 3), "\n")
#debug concat("max(2,8,-3,7,8.5,1) = ", str(max(2,8,-3,7,8.5,1), 0, 3), "\n")
