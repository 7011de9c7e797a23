#version 3.7;
#macro Increment(V) #declare V = V + 1; #end
#declare Count = 5;
Increment(Count)
Increment(Count)
#debug concat("Count = ", str(Count, 0, 0), "\n")
