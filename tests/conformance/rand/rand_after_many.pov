#version 3.7;
#declare R = seed(31337);
#for (I, 1, 10000) #declare V = rand(R); #end
#debug concat("V = ", str(V, 0, 12), "\n")
#debug concat("rand(R) = ", str(rand(R), 0, 12), "\n")
