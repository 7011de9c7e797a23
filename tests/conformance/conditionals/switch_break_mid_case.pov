#version 3.7;
#switch (2)
  #case (2)
    #debug "first part\n"
    #if (1) #break #end
    #debug "never\n"
  #case (3) #debug "three\n"
#end
#debug "after switch\n"
