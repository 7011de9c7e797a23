#version 3.7;
#macro Scale() 3 #end
#declare F = function { x * Scale() }
#debug concat("F(2, 0, 0) = ", str(F(2, 0, 0), 0, 3), "\n")
