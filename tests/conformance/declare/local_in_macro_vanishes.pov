#version 3.7;
#macro M()
  #local Temp = 1;
#end
M()
#ifdef (Temp) #debug "defined\n" #else #debug "undefined\n" #end
