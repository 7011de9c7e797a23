#version 3.7;
#debug concat("atan2(1,1) = ", str(atan2(1,1), 0, 9), "\n")
#debug concat("atan2(1,-1) = ", str(atan2(1,-1), 0, 9), "\n")
#debug concat("atan2(-1,-1) = ", str(atan2(-1,-1), 0, 9), "\n")
#debug concat("atan2(-1,1) = ", str(atan2(-1,1), 0, 9), "\n")
