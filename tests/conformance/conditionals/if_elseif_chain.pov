#version 3.7;
#for (V, 0, 3)
  #if (V = 0) #debug "zero\n" #elseif (V = 1) #debug "one\n" #elseif (V = 2) #debug "two\n" #else #debug "many\n" #end
#end
