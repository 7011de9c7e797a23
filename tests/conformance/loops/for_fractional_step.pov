#version 3.7;
#for (I, 0, 1, 0.1) #debug concat(str(I, 0, 2), " ") #end
#debug "\n"
