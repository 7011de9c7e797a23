#version 3.7;
#include "arrays.inc"
#declare R = seed(3);
#declare A = array[4] {"a", "b", "c", "d"};
#for (I, 1, 5) #debug Rand_Array_Item(A, R) #end
#debug "\n"
