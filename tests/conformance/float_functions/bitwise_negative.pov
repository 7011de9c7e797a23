#version 3.7;
#debug concat("bitwise_and(-1,255) = ", str(bitwise_and(-1,255), 0, 0), "\n")
#debug concat("bitwise_or(-8,3) = ", str(bitwise_or(-8,3), 0, 0), "\n")
#debug concat("bitwise_xor(-1,1) = ", str(bitwise_xor(-1,1), 0, 0), "\n")
