#version 3.7;
#debug concat("mod(1e15+7,10) = ", str(mod(1e15+7,10), 0, 3), "\n")
#debug concat("mod(pow(2,40),3) = ", str(mod(pow(2,40),3), 0, 3), "\n")
