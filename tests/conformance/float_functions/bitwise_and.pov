#version 3.7;
#debug concat("bitwise_and(12,10) = ", str(bitwise_and(12,10), 0, 0), "\n")
#debug concat("bitwise_and(255,15,7) = ", str(bitwise_and(255,15,7), 0, 0), "\n")
#debug concat("bitwise_and(7.9,3.2) = ", str(bitwise_and(7.9,3.2), 0, 0), "\n")
