#version 3.7;
#declare A = 1;
#undef A
#debug concat("defined(A) = ", str(defined(A), 0, 0), "\n")
