#version 3.7;
#debug concat("atan2(0,1) = ", str(atan2(0,1), 0, 9), "\n")
#debug concat("atan2(1,0) = ", str(atan2(1,0), 0, 9), "\n")
#debug concat("atan2(0,-1) = ", str(atan2(0,-1), 0, 9), "\n")
#debug concat("atan2(-1,0) = ", str(atan2(-1,0), 0, 9), "\n")
