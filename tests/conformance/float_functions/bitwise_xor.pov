#version 3.7;
#debug concat("bitwise_xor(12,10) = ", str(bitwise_xor(12,10), 0, 0), "\n")
#debug concat("bitwise_xor(1,3,7) = ", str(bitwise_xor(1,3,7), 0, 0), "\n")
#debug concat("bitwise_xor(5,5) = ", str(bitwise_xor(5,5), 0, 0), "\n")
