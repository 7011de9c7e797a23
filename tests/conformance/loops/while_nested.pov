#version 3.7;
#declare I = 0;
#while (I < 3)
  #declare J = 0;
  #while (J < I)
    #debug concat(str(I, 0, 0), str(J, 0, 0), " ")
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
#debug "\n"
