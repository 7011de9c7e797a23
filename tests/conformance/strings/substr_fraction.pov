#version 3.7;
#debug concat("substr(\"ABCDEF\", 2.7, 3.9) = [", substr("ABCDEF", 2.7, 3.9), "]\n")
