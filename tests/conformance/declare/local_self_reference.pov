#version 3.7;
#macro Outer()
  #local D = 10;
  Inner()
#end
#macro Inner()
  #local D = D + 1;
#end
Outer()
