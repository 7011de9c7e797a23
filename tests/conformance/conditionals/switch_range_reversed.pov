#version 3.7;
#switch (3)
  #range (5, 1) #debug "reversed range matched\n" #break
  #else #debug "reversed range empty\n"
#end
