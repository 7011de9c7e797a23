#version 3.7;
#macro M()
  #local D = 1;
  #local D = D + 1;
  #debug concat(str(D, 0, 0), "\n")
#end
M()
