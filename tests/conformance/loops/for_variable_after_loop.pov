#version 3.7;
#for (I, 1, 10, 3) #end
#debug concat("I = ", str(I, 0, 0), "\n")
