#version 3.7;
#declare A = 1;
#debug concat("(defined(A) & !defined(B)) = ", str((defined(A) & !defined(B)), 0, 0), "\n")
#debug concat("defined(A) + defined(A) = ", str(defined(A) + defined(A), 0, 0), "\n")
