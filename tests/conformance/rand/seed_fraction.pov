#version 3.7;
#declare R = seed(7.9);
#for (I, 1, 5)
  #debug concat(str(rand(R), 0, 12), "\n")
#end
