#version 3.7;
#debug concat("6/3*2 = ", str(6/3*2, 0, 3), "\n")
#debug concat("6/(3*2) = ", str(6/(3*2), 0, 3), "\n")
#debug concat("1+6/3-1 = ", str(1+6/3-1, 0, 3), "\n")
