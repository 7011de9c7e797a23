#version 3.7;
#debug concat("1e-2 = ", str(1e-2, 0, 9), "\n")
#debug concat("1e+2 = ", str(1e+2, 0, 9), "\n")
#debug concat("-1.5e-3 = ", str(-1.5e-3, 0, 9), "\n")
#debug concat("3e2*2e-2 = ", str(3e2*2e-2, 0, 9), "\n")
