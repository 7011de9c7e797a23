#version 3.7;
#debug concat("-0.0001 = ", str(-0.0001, 0, 2), "\n")
#debug concat("-0.004 = ", str(-0.004, 0, 2), "\n")
#debug concat("-1e-20 = ", str(-1e-20, 0, 2), "\n")
