#version 3.7;
#debug concat("mod(7.5,2) = ", str(mod(7.5,2), 0, 9), "\n")
#debug concat("mod(-7.5,2) = ", str(mod(-7.5,2), 0, 9), "\n")
#debug concat("mod(1,0.3) = ", str(mod(1,0.3), 0, 9), "\n")
#debug concat("mod(5.5,-1.5) = ", str(mod(5.5,-1.5), 0, 9), "\n")
