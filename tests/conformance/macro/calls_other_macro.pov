#version 3.7;
#macro Inc(A) (A + 1) #end
#macro IncTwice(A) Inc(Inc(A)) #end
#debug concat("IncTwice(5) = ", str(IncTwice(5), 0, 0), "\n")
