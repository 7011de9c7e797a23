#version 3.7;
#debug concat("mod(-7,3) = ", str(mod(-7,3), 0, 6), "\n")
#debug concat("mod(7,-3) = ", str(mod(7,-3), 0, 6), "\n")
#debug concat("mod(-7,-3) = ", str(mod(-7,-3), 0, 6), "\n")
#debug concat("mod(-1,5) = ", str(mod(-1,5), 0, 6), "\n")
