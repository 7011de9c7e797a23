#version 3.7;
#include "arrays.inc"
#declare A = array[6] {5, 3, 9, 1, 7, 2};
Sort_Array(A)
#for (I, 0, 5) #debug concat(str(A[I], 0, 0), " ") #end
#debug "\n"
