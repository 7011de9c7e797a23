#version 3.7;
#declare S = 0;
#declare I = 0;
#while (I < 1000)
  #declare S = S + 0.001;
  #declare I = I + 1;
#end
#debug concat("S = ", str(S, 0, 17), "\n")
