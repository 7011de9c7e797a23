#version 3.7;
#for (I, 1, 5)
  #debug concat(str(I, 0, 0), "\n")
  #if (I = 3) #error "third" #end
#end
