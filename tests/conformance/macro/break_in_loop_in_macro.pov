#version 3.7;
#macro M()
  #for (I, 1, 10)
    #if (I = 3) #break #end
    #debug concat(str(I, 0, 0), "\n")
  #end
  #debug "macro continues\n"
#end
M()
