#version 3.7;
#for (I, 2, 2) #debug concat(str(I, 0, 0), "\n") #end
