#version 3.7;
#declare A = 1;
#macro M(A) (A * 100) #end
#debug concat("M(2) = ", str(M(2), 0, 0), "\n")
#debug concat("A = ", str(A, 0, 0), "\n")
