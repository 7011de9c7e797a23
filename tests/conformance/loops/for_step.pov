#version 3.7;
#for (I, 0, 330, 30) #debug concat(str(I, 0, 0), " ") #end
#debug "\n"
