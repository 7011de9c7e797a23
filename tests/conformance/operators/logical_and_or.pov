#version 3.7;
#debug concat("(1&0) = ", str((1&0), 0, 0), "\n")
#debug concat("(1&1) = ", str((1&1), 0, 0), "\n")
#debug concat("(0|0) = ", str((0|0), 0, 0), "\n")
#debug concat("(0|1) = ", str((0|1), 0, 0), "\n")
#debug concat("(2&3) = ", str((2&3), 0, 0), "\n")
#debug concat("(-1|0) = ", str((-1|0), 0, 0), "\n")
