#version 3.7;
#macro SetLocal(V) #local V = 99; #end
#declare Count = 5;
SetLocal(Count)
#debug concat("Count = ", str(Count, 0, 0), "\n")
