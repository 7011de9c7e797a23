#version 3.7;
#declare I = 0;
#while (1)
  #declare I = I + 1;
  #if (I > 4) #break #end
#end
#debug concat("I = ", str(I, 0, 0), "\n")
