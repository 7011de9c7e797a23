#version 3.7;
#macro M(P) #end
M(5)
#debug concat("defined(P) = ", str(defined(P), 0, 0), "\n")
