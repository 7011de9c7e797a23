#version 3.7;
#switch (1)
  #case (1) #debug "case 1\n"
  #range (0, 5) #debug "range 0..5\n"
  #case (9) #debug "case 9\n"
#end
