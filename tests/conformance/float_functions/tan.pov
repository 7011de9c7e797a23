#version 3.7;
#debug concat("tan(0) = ", str(tan(0), 0, 9), "\n")
#debug concat("tan(pi/4) = ", str(tan(pi/4), 0, 9), "\n")
#debug concat("tan(-1) = ", str(tan(-1), 0, 9), "\n")
#debug concat("tan(1.5) = ", str(tan(1.5), 0, 9), "\n")
