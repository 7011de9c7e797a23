#version 3.7;
#debug concat("(1e-11 < 2e-11) = ", str((1e-11 < 2e-11), 0, 0), "\n")
#debug concat("(1 < 1+1e-11) = ", str((1 < 1+1e-11), 0, 0), "\n")
#debug concat("(1 <= 1-1e-11) = ", str((1 <= 1-1e-11), 0, 0), "\n")
#debug concat("(1 >= 1+1e-11) = ", str((1 >= 1+1e-11), 0, 0), "\n")
