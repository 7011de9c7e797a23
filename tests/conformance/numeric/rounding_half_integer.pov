#version 3.7;
#debug concat("0.5 = ", str(0.5, 0, 0), "\n")
#debug concat("1.5 = ", str(1.5, 0, 0), "\n")
#debug concat("2.5 = ", str(2.5, 0, 0), "\n")
#debug concat("-2.5 = ", str(-2.5, 0, 0), "\n")
#debug concat("3.5 = ", str(3.5, 0, 0), "\n")
