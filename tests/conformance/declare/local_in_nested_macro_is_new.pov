#version 3.7;
#macro Outer()
  #local D = 10;
  Inner()
  #debug concat("outer sees ", str(D, 0, 0), "\n")
#end
#macro Inner()
  #local E = D + 1;
  #local D = E;
  #debug concat("inner sees ", str(D, 0, 0), "\n")
#end
Outer()
