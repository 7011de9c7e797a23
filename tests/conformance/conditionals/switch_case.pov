#version 3.7;
#for (V, 1, 3)
  #switch (V)
    #case (1) #debug "one\n" #break
    #case (2) #debug "two\n" #break
    #else #debug "other\n"
  #end
#end
