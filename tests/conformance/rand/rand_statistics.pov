#version 3.7;
#declare R = seed(2024);
#declare Sum = 0;
#declare Lo = 1;
#declare Hi = 0;
#for (I, 1, 1000)
  #declare V = rand(R);
  #declare Sum = Sum + V;
  #declare Lo = min(Lo, V);
  #declare Hi = max(Hi, V);
#end
#debug concat("Sum = ", str(Sum, 0, 9), "\n")
#debug concat("Lo = ", str(Lo, 0, 12), "\n")
#debug concat("Hi = ", str(Hi, 0, 12), "\n")
