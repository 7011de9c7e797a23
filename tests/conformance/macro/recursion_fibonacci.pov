#version 3.7;
#macro Fib(N)
  #if (N < 2) N #else (Fib(N - 1) + Fib(N - 2)) #end
#end
#for (I, 0, 12) #debug concat(str(Fib(I), 0, 0), " ") #end
#debug "\n"
