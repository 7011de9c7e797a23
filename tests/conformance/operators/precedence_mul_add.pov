#version 3.7;
#debug concat("1+2*3 = ", str(1+2*3, 0, 3), "\n")
#debug concat("2*3+1 = ", str(2*3+1, 0, 3), "\n")
#debug concat("(1+2)*3 = ", str((1+2)*3, 0, 3), "\n")
#debug concat("2*3-4/2 = ", str(2*3-4/2, 0, 3), "\n")
