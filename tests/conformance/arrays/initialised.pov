#version 3.7;
#declare A = array[4] {1, 2, 3, 4};
#for (I, 0, 3) #debug concat(str(A[I], 0, 0), " ") #end
#debug "\n"
