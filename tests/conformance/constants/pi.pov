#version 3.7;
#debug concat("pi = ", str(pi, 0, 20), "\n")
#debug concat("pi*2 = ", str(pi*2, 0, 20), "\n")
#debug concat("-pi = ", str(-pi, 0, 20), "\n")
