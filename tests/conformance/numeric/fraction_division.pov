#version 3.7;
#debug concat("7/2 = ", str(7/2, 0, 12), "\n")
#debug concat("-7/2 = ", str(-7/2, 0, 12), "\n")
#debug concat("1/8 = ", str(1/8, 0, 12), "\n")
#debug concat("1/7 = ", str(1/7, 0, 12), "\n")
