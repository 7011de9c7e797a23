#version 3.7;
#declare R = seed(42);
#for (I, 1, 12)
  #debug concat(str(rand(R), 0, 12), "\n")
#end
