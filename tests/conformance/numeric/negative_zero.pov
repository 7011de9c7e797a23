#version 3.7;
#debug concat("-0 = ", str(-0, 0, 0), "\n")
#debug concat("0*-1 = ", str(0*-1, 0, 0), "\n")
#debug concat("-0.0001 = ", str(-0.0001, 0, 0), "\n")
#debug concat("-0.4 = ", str(-0.4, 0, 0), "\n")
