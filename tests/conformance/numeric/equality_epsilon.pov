#version 3.7;
#debug concat("(1 = 1+1e-11) = ", str((1 = 1+1e-11), 0, 0), "\n")
#debug concat("(1 = 1+1e-9) = ", str((1 = 1+1e-9), 0, 0), "\n")
#debug concat("(1 != 1+1e-11) = ", str((1 != 1+1e-11), 0, 0), "\n")
#debug concat("(0 = 1e-10) = ", str((0 = 1e-10), 0, 0), "\n")
