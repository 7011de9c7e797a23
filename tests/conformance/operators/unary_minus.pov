#version 3.7;
#debug concat("-2*3 = ", str(-2*3, 0, 3), "\n")
#debug concat("-(2+3) = ", str(-(2+3), 0, 3), "\n")
#debug concat("--2 = ", str(--2, 0, 3), "\n")
#debug concat("-+-2 = ", str(-+-2, 0, 3), "\n")
#debug concat("+5 = ", str(+5, 0, 3), "\n")
#debug concat("3--2 = ", str(3--2, 0, 3), "\n")
