#version 3.7;
#declare A = seed(5);
#declare B = A;
#debug concat(str(rand(A), 0, 9), " ", str(rand(B), 0, 9), "\n")
