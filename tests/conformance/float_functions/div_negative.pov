#version 3.7;
#debug concat("div(-7,2) = ", str(div(-7,2), 0, 3), "\n")
#debug concat("div(7,-2) = ", str(div(7,-2), 0, 3), "\n")
#debug concat("div(-7,-2) = ", str(div(-7,-2), 0, 3), "\n")
#debug concat("div(-1,3) = ", str(div(-1,3), 0, 3), "\n")
