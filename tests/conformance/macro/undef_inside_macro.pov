#version 3.7;
#declare G = 1;
#macro Remove() #undef G #end
Remove()
#debug concat("defined(G) = ", str(defined(G), 0, 0), "\n")
