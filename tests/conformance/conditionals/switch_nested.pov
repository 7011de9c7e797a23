#version 3.7;
#switch (1)
  #case (1)
    #switch (2)
      #case (2) #debug "inner two\n" #break
    #end
    #debug "outer one\n"
  #break
#end
