#version 3.7;
#debug concat("ceil(1.2) = ", str(ceil(1.2), 0, 3), "\n")
#debug concat("ceil(-1.2) = ", str(ceil(-1.2), 0, 3), "\n")
#debug concat("ceil(2) = ", str(ceil(2), 0, 3), "\n")
#debug concat("ceil(-0.5) = ", str(ceil(-0.5), 0, 3), "\n")
#debug concat("ceil(0.0000001) = ", str(ceil(0.0000001), 0, 3), "\n")
