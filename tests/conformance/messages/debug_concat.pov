#version 3.7;
#debug concat("a", "b", "\n")
