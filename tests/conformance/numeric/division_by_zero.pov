#version 3.7;
#debug concat("1/0 = ", str(1/0, 0, 3), "\n")
#debug concat("-1/0 = ", str(-1/0, 0, 3), "\n")
#debug concat("0/0 = ", str(0/0, 0, 3), "\n")
