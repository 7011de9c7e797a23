#version 3.7;
#declare I = 0;
#declare Sum = 0;
#while (I < 100)
  #declare Sum = Sum + I;
  #declare I = I + 1;
#end
#debug concat("Sum = ", str(Sum, 0, 0), "\n")
