#version 3.7;
#macro Make() #local L = function(a) { a + 1 } L(1) #end
#debug concat("Make() = ", str(Make(), 0, 0), "\n")
