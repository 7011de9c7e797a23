#version 3.7;
#switch (4)
  #case (1) #debug "one\n" #break
#end
#debug "done\n"
