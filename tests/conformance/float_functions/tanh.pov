#version 3.7;
#debug concat("tanh(0) = ", str(tanh(0), 0, 9), "\n")
#debug concat("tanh(1) = ", str(tanh(1), 0, 9), "\n")
#debug concat("tanh(-20) = ", str(tanh(-20), 0, 9), "\n")
