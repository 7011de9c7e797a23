#version 3.7;
#debug concat("1/3 = ", str(1/3, 0, 20), "\n")
#debug concat("2/3 = ", str(2/3, 0, 20), "\n")
#debug concat("10/3 = ", str(10/3, 0, 20), "\n")
#debug concat("-1/3 = ", str(-1/3, 0, 20), "\n")
