#version 3.7;
#switch (5)
  #range (0, 10) #debug "first range\n" #break
  #case (5) #debug "second case\n" #break
#end
