#version 3.7;
#for (A, -2, 2)
  #debug concat(str(A, 0, 0), ": ", str(select(A, -1, 1), 0, 0), "\n")
#end
