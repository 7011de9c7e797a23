#version 3.7;
#debug concat("div(7.9,2) = ", str(div(7.9,2), 0, 3), "\n")
#debug concat("div(-7.5,2.5) = ", str(div(-7.5,2.5), 0, 3), "\n")
#debug concat("div(5,0.3) = ", str(div(5,0.3), 0, 3), "\n")
