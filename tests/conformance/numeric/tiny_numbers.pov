#version 3.7;
#debug concat("1e-7 = ", str(1e-7, 0, 20), "\n")
#debug concat("1e-15 = ", str(1e-15, 0, 20), "\n")
#debug concat("1e-300*1e-300 = ", str(1e-300*1e-300, 0, 20), "\n")
