#version 3.7;
#debug concat("8/2/2 = ", str(8/2/2, 0, 3), "\n")
#debug concat("2-3-4 = ", str(2-3-4, 0, 3), "\n")
#debug concat("2*3/4 = ", str(2*3/4, 0, 3), "\n")
#debug concat("1-2+3 = ", str(1-2+3, 0, 3), "\n")
