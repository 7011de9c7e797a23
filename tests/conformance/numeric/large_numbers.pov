#version 3.7;
#debug concat("1e15 = ", str(1e15, 0, 0), "\n")
#debug concat("pow(2,53) = ", str(pow(2,53), 0, 0), "\n")
#debug concat("pow(2,53)+1 = ", str(pow(2,53)+1, 0, 0), "\n")
#debug concat("1e20 = ", str(1e20, 0, 0), "\n")
#debug concat("123456789012345678 = ", str(123456789012345678, 0, 0), "\n")
