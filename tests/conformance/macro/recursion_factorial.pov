#version 3.7;
#macro Fact(N)
  #if (N <= 1) 1 #else (N * Fact(N - 1)) #end
#end
#debug concat("Fact(5) = ", str(Fact(5), 0, 0), "\n")
#debug concat("Fact(10) = ", str(Fact(10), 0, 0), "\n")
