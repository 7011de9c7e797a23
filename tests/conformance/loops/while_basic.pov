#version 3.7;
#declare I = 0;
#while (I < 5)
  #debug concat(str(I, 0, 0), "\n")
  #declare I = I + 1;
#end
