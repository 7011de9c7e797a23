#version 3.7;
#debug "before\n"
#switch (1)
  #else #debug "else\n"
  #case (1) #debug "one\n"
#end
