#version 3.7;
#macro First() Second() #end
#macro Second() 2 #end
#debug concat("First() = ", str(First(), 0, 0), "\n")
