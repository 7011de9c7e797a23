#version 3.7;
#debug concat("1e3 = ", str(1e3, 0, 6), "\n")
#debug concat("1E-3 = ", str(1E-3, 0, 6), "\n")
#debug concat(".5 = ", str(.5, 0, 6), "\n")
#debug concat("5. = ", str(5., 0, 6), "\n")
#debug concat("1.5e+2 = ", str(1.5e+2, 0, 6), "\n")
#debug concat("00012 = ", str(00012, 0, 6), "\n")
#debug concat("2.5e0 = ", str(2.5e0, 0, 6), "\n")
