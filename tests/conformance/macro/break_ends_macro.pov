#version 3.7;
#macro M()
  #debug "first\n"
  #break
  #debug "never\n"
#end
M()
#debug "after\n"
