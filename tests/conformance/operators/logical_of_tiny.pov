#version 3.7;
#debug concat("(1e-11&1) = ", str((1e-11&1), 0, 0), "\n")
#debug concat("(1e-11|0) = ", str((1e-11|0), 0, 0), "\n")
#debug concat("(1&0.5) = ", str((1&0.5), 0, 0), "\n")
