#version 3.7;
#debug concat("pow(-8,1/3) = ", str(pow(-8,1/3), 0, 6), "\n")
