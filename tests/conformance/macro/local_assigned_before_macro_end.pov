#version 3.7;
#macro Find(P) #local Q = P + 1; Q; #end
#macro Grow(P)
  #local Found = Find(P)
  #local Again = Find(Found)
  #debug concat(str(Found, 0, 0), " ", str(Again, 0, 0), "\n")
#end
Grow(4)
#declare G = Find(1)
#debug concat("G = ", str(G, 0, 0), "\n")
