#version 3.7;
#macro Len(S) strlen(S) #end
#debug concat("Len(concat(\"abc\", \"de\")) = ", str(Len(concat("abc", "de")), 0, 0), "\n")
