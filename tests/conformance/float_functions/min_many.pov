#version 3.7;
#debug concat("min(3,1,2) = ", str(min(3,1,2), 0, 3), "\n")
#debug concat("min(5,4,3,2,1,0,-1) = ", str(min(5,4,3,2,1,0,-1), 0, 3), "\n")
#debug concat("min(2,8,-3,7,-3.5) = ", str(min(2,8,-3,7,-3.5), 0, 3), "\n")
