#version 3.7;
// The macros of arrays.inc on small arrays.
#include "arrays.inc"
// Ten items a line: POV-Ray wraps longer #debug lines.
#macro ShowArray(Label, A)
  #local Text = Label;
  #for (I, 0, dimension_size(A, 1) - 1)
    #ifdef (A[I])
      #local Text = concat(Text, " ", str(A[I], 0, 1));
    #else
      #local Text = concat(Text, " -");
    #end
    #if (mod(I, 10) = 9)
      #debug concat(Text, "\n")
      #local Text = "  ";
    #end
  #end
  #debug concat(Text, "\n")
#end
#declare Numbers = array[25] { 5, 3, 9, 1, 1, 8, -2, 7.5, 0, 3, 12, 4, 4, 6, -7, 2, 11, 10, 3.5, 0.5, 9, 13, -1, 2, 6 }
#declare Copy = Numbers;
Sort_Array(Copy)
ShowArray("Sort_Array", Copy)
#declare Copy = Numbers;
Sort_Partial_Array(Copy, 3, 15)
ShowArray("Sort_Partial_Array", Copy)
#declare Small = array[4] { 2, -1, 0.5, 2 }
Sort_Array(Small)
ShowArray("Sort_Array small", Small)
#declare Copy = Numbers;
Reverse_Array(Copy)
ShowArray("Reverse_Array", Copy)
#declare Odd = array[5] { 1, 2, 3, 4, 5 }
Reverse_Array(Odd)
ShowArray("Reverse_Array odd", Odd)
#declare Grown = array[3] { 1, 2, 3 }
Resize_Array(Grown, 5)
ShowArray("Resize_Array grown", Grown)
#declare Shrunk = array[5] { 1, 2, 3, 4, 5 }
Resize_Array(Shrunk, 2)
ShowArray("Resize_Array shrunk", Shrunk)
#declare S = seed(42);
#for (I, 1, 8) #debug concat("Rand_Array_Item ", str(Rand_Array_Item(Numbers, S), 0, 2), "\n") #end
// A redefined comparison sorts descending by absolute value.
#macro Sort_Compare(Array, IdxA, IdxB) (abs(Array[IdxA]) > abs(Array[IdxB])) #end
#declare Copy = array[9] { 3, -8, 1, 0, 5, -2, 7, -6, 4 }
Sort_Array(Copy)
ShowArray("Sort_Array custom", Copy)
