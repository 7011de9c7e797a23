#version 3.7;
#debug concat("asc(chr(90)) = ", str(asc(chr(90)), 0, 0), "\n")
#debug concat("chr(asc(\"q\")) = [", chr(asc("q")), "]\n")
