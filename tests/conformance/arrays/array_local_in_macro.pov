#version 3.7;
#macro M() #local A = array[2] {3, 4}; (A[0] + A[1]) #end
#debug concat("M() = ", str(M(), 0, 0), "\n")
