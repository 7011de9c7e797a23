#version 3.7;
#for (I, 1, 100)
  #if (I * I > 20) #break #end
  #debug concat(str(I, 0, 0), " ")
#end
#debug "\n"
#debug concat("I = ", str(I, 0, 0), "\n")
