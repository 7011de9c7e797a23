#version 3.7;
#switch (0.1 + 0.2)
  #case (0.3) #debug "equal within epsilon\n" #break
  #else #debug "not equal\n"
#end
