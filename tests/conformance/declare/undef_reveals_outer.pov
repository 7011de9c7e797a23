#version 3.7;
#declare A = 1;
#macro M()
  #local A = 2;
  #undef A
  #debug concat("after undef: ", str(A, 0, 0), "\n")
#end
M()
