#version 3.7;
#declare A = 1;
#declare A = "now a string";
#debug concat("A = [", A, "]\n")
