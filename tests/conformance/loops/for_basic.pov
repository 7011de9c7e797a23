#version 3.7;
#for (I, 1, 5) #debug concat(str(I, 0, 0), " ") #end
#debug "\n"
