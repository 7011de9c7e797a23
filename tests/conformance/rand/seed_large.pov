#version 3.7;
#declare R = seed(4294967295);
#for (I, 1, 5)
  #debug concat(str(rand(R), 0, 12), "\n")
#end
