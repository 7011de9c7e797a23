#version 3.7;
#declare R = seed(0);
#for (I, 1, 60)
  #debug concat(str(rand(R), 0, 9), "\n")
#end
