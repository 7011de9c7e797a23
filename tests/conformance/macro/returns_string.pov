#version 3.7;
#macro Greet(Name) concat("Hi ", Name) #end
#debug concat("Greet(\"Ann\") = [", Greet("Ann"), "]\n")
