#version 3.7;
#declare A = seed(99);
#declare B = seed(99);
#debug concat(str(rand(A), 0, 9), " ", str(rand(A), 0, 9), "\n")
#debug concat(str(rand(B), 0, 9), " ", str(rand(B), 0, 9), "\n")
