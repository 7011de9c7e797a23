#version 3.7;
#for (I, 5, 1, -1) #debug concat(str(I, 0, 0), " ") #end
#debug "\n"
