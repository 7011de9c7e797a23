#version 3.7;
#macro DivMod(A, B, Q, R)
  #declare Q = div(A, B);
  #declare R = mod(A, B);
#end
#declare Q = 0;
#declare R = 0;
DivMod(17, 5, Q, R)
#debug concat("Q = ", str(Q, 0, 0), "\n")
#debug concat("R = ", str(R, 0, 0), "\n")
