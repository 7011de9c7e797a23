#version 3.7;
#debug concat("0.125 = ", str(0.125, 0, 2), "\n")
#debug concat("0.375 = ", str(0.375, 0, 2), "\n")
#debug concat("1.005 = ", str(1.005, 0, 2), "\n")
#debug concat("2.675 = ", str(2.675, 0, 2), "\n")
