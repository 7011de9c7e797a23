#version 3.7;
#for (I, 1, 3)
  #switch (I)
    #case (2) #break
    #else #debug "not two\n"
  #end
  #debug concat("iteration ", str(I, 0, 0), "\n")
#end
