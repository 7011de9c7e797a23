#version 3.7;
#switch (1)
  #debug "before any case\n"
  #case (1) #debug "case 1\n" #break
#end
