#version 3.7;
#debug concat("int(3e9) = ", str(int(3e9), 0, 0), "\n")
#debug concat("int(-3e9) = ", str(int(-3e9), 0, 0), "\n")
#debug concat("int(1e15+0.5) = ", str(int(1e15+0.5), 0, 0), "\n")
