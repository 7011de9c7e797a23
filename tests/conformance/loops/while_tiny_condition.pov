#version 3.7;
#declare C = 0;
#while (1e-11)
  #declare C = C + 1;
  #break
#end
#debug concat("C = ", str(C, 0, 0), "\n")
