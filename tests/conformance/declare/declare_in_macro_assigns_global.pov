#version 3.7;
#declare A = 1;
#macro M()
  #declare A = 2;
#end
M()
#debug concat("A = ", str(A, 0, 0), "\n")
