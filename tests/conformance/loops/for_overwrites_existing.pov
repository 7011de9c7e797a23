#version 3.7;
#declare I = 100;
#for (I, 1, 2) #end
#debug concat("I = ", str(I, 0, 0), "\n")
