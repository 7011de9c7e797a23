#version 3.7;
#for (I, 0.5, 3.2) #debug concat(str(I, 0, 2), " ") #end
#debug "\n"
