#version 3.7;
#include "arrays.inc"
#declare A = array[4] {1, 2, 3, 4};
Reverse_Array(A)
#for (I, 0, 3) #debug concat(str(A[I], 0, 0), " ") #end
#debug "\n"
