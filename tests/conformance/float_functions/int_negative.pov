#version 3.7;
#debug concat("int(-1.5) = ", str(int(-1.5), 0, 3), "\n")
#debug concat("int(-0.5) = ", str(int(-0.5), 0, 3), "\n")
#debug concat("int(-2.7) = ", str(int(-2.7), 0, 3), "\n")
#debug concat("int(-3) = ", str(int(-3), 0, 3), "\n")
