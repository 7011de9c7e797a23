#version 3.7;
#macro Loop() #for (K, 1, 3) #end #end
Loop()
#debug concat("defined(K) = ", str(defined(K), 0, 0), "\n")
