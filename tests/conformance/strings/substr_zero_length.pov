#version 3.7;
#debug concat("substr(\"ABC\", 2, 0) = [", substr("ABC", 2, 0), "]\n")
