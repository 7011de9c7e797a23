#version 3.7;
#while (0)
  #debug "never\n"
#end
#debug "done\n"
