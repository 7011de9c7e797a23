#version 3.7;
#macro Depth(N)
  #local Mine = N * 10;
  #if (N > 0) Depth(N - 1) #end
  #debug concat("level ", str(N, 0, 0), " keeps ", str(Mine, 0, 0), "\n")
#end
Depth(3)
