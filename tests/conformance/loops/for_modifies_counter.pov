#version 3.7;
#for (I, 1, 10)
  #debug concat(str(I, 0, 0), " ")
  #declare I = I + 2;
#end
#debug "\n"
