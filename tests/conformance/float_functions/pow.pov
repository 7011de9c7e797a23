#version 3.7;
#debug concat("pow(2,10) = ", str(pow(2,10), 0, 9), "\n")
#debug concat("pow(2,-1) = ", str(pow(2,-1), 0, 9), "\n")
#debug concat("pow(9,0.5) = ", str(pow(9,0.5), 0, 9), "\n")
#debug concat("pow(10,-3) = ", str(pow(10,-3), 0, 9), "\n")
#debug concat("pow(0,2) = ", str(pow(0,2), 0, 9), "\n")
