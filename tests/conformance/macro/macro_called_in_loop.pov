#version 3.7;
#macro Sq(A) (A * A) #end
#declare S = 0;
#for (I, 1, 10) #declare S = S + Sq(I); #end
#debug concat("S = ", str(S, 0, 0), "\n")
