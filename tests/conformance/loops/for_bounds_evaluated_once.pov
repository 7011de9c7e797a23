#version 3.7;
#declare N = 3;
#for (I, 1, N)
  #declare N = 10;
  #debug concat(str(I, 0, 0), " ")
#end
#debug "\n"
