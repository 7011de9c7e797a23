#version 3.7;
#switch (7)
  #case (1) #debug "case 1\n" #break
  #case (2) #debug "case 2\n"
  #else #debug "else\n"
#end
