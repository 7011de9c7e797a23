#version 3.7;
#debug concat("0.1+0.2 = ", str(0.1+0.2, 0, 20), "\n")
#debug concat("0.3 = ", str(0.3, 0, 20), "\n")
#debug concat("(0.1+0.2)-0.3 = ", str((0.1+0.2)-0.3, 0, 20), "\n")
