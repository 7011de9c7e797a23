#version 3.7;
#for (I, 1, 3)
  #for (J, 1, I) #debug "*" #end
  #debug "\n"
#end
