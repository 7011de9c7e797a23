#version 3.7;
#declare A = 1;
#macro M()
  #local A = 2;
  #debug concat("inside: ", str(A, 0, 0), "\n")
#end
M()
#debug concat("outside: ", str(A, 0, 0), "\n")
