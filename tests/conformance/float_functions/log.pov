#version 3.7;
#debug concat("log(1) = ", str(log(1), 0, 9), "\n")
#debug concat("log(10) = ", str(log(10), 0, 9), "\n")
#debug concat("log(1000) = ", str(log(1000), 0, 9), "\n")
#debug concat("log(2) = ", str(log(2), 0, 9), "\n")
#debug concat("log(0.01) = ", str(log(0.01), 0, 9), "\n")
