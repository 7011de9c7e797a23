#version 3.7;
#declare D = 1;
#macro M() #declare D = D + 1; #end
M()
#debug concat("D = ", str(D, 0, 0), "\n")
