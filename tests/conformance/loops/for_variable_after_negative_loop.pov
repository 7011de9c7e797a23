#version 3.7;
#for (I, 3, 0, -2) #end
#debug concat("I = ", str(I, 0, 0), "\n")
