#version 3.7;
#declare A = seed(1);
#declare B = seed(2);
#for (I, 1, 4)
  #debug concat(str(rand(A), 0, 9), " ", str(rand(B), 0, 9), "\n")
#end
