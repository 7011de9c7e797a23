#version 3.7;
#debug concat("pow(-2,3) = ", str(pow(-2,3), 0, 9), "\n")
#debug concat("pow(-2,2) = ", str(pow(-2,2), 0, 9), "\n")
#debug concat("pow(-8,-1) = ", str(pow(-8,-1), 0, 9), "\n")
