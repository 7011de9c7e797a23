#version 3.7;
#declare A = 1;
#debug concat("defined(A) = ", str(defined(A), 0, 0), "\n")
#debug concat("defined(B) = ", str(defined(B), 0, 0), "\n")
#debug concat("defined(pi) = ", str(defined(pi), 0, 0), "\n")
