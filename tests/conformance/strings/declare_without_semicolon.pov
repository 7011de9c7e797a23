#version 3.7;
#declare S = "no semicolon"
#declare T = concat(S, "!")
#debug concat("T = [", T, "]\n")
