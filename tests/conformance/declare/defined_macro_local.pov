#version 3.7;
#macro M()
  #local L = 1;
  #debug concat("inside: ", str(defined(L), 0, 0), "\n")
#end
M()
#debug concat("outside: ", str(defined(L), 0, 0), "\n")
