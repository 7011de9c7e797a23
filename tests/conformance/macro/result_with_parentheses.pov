#version 3.7;
#macro Sum(A, B) (A + B) #end
#debug concat("Sum(1, 2) * 10 = ", str(Sum(1, 2) * 10, 0, 0), "\n")
