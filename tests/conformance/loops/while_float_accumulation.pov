#version 3.7;
#declare T = 0;
#declare N = 0;
#while (T < 1)
  #declare T = T + 0.1;
  #declare N = N + 1;
#end
#debug concat("N = ", str(N, 0, 0), "\n")
#debug concat("T = ", str(T, 0, 17), "\n")
