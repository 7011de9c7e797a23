#version 3.7;
#macro M() 1 #end
#debug concat("M() = ", str(M(), 0, 0), "\n")
#macro M() 2 #end
#debug concat("M() = ", str(M(), 0, 0), "\n")
