#version 3.7;
#for (I, 1, 0, -0.25) #debug concat(str(I, 0, 2), " ") #end
#debug "\n"
