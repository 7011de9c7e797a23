#version 3.7;
#switch (1)
  #case (1) #debug "case 1\n"
  #else #debug "else\n"
#end
