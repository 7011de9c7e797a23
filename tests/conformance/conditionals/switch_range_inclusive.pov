#version 3.7;
#switch (5)
  #range (1, 5) #debug "upper bound included\n" #break
#end
#switch (1)
  #range (1, 5) #debug "lower bound included\n" #break
#end
