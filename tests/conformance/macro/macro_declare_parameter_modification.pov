#version 3.7;
#macro M(A)
  #declare A = A * 2;
  A
#end
#declare V = 3;
#debug concat("M(V) = ", str(M(V), 0, 0), "\n")
#debug concat("V = ", str(V, 0, 0), "\n")
