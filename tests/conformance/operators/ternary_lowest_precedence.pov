#version 3.7;
#debug concat("(1+1 ? 10 : 20) = ", str((1+1 ? 10 : 20), 0, 0), "\n")
#debug concat("(1 ? 2 : 3+4) = ", str((1 ? 2 : 3+4), 0, 0), "\n")
#debug concat("(0 ? 2 : 3+4) = ", str((0 ? 2 : 3+4), 0, 0), "\n")
#debug concat("(1-1 ? 5 : 6*2) = ", str((1-1 ? 5 : 6*2), 0, 0), "\n")
