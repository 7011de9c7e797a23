#version 3.7;
#debug concat(str(rand(seed(3)), 0, 12), " ", str(rand(seed(3)), 0, 12), "\n")
