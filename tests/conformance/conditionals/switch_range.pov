#version 3.7;
#for (V, 0, 10, 2.5)
  #switch (V)
    #range (0, 2.5) #debug "low\n" #break
    #range (2.6, 7.5) #debug "mid\n" #break
    #else #debug "high\n"
  #end
#end
