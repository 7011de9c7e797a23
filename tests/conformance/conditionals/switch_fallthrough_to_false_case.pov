#version 3.7;
#switch (1)
  #case (1) #debug "case 1\n"
  #case (2) #debug "case 2\n"
  #case (3) #debug "case 3\n" #break
#end
