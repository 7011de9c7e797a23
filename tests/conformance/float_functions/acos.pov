#version 3.7;
#debug concat("acos(0.5) = ", str(acos(0.5), 0, 9), "\n")
#debug concat("acos(-1) = ", str(acos(-1), 0, 9), "\n")
#debug concat("acos(1) = ", str(acos(1), 0, 9), "\n")
#debug concat("acos(0) = ", str(acos(0), 0, 9), "\n")
