#version 3.7;
#macro Show(A, B)
  #debug concat(str(A, 0, 1), " ", str(B, 0, 1), "\n")
#end
Show(1, 2.5)
Show(3*2, -1)
