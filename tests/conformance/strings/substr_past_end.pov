#version 3.7;
#debug "before\n"
#debug concat("substr(\"ABC\", 2, 5) = [", substr("ABC", 2, 5), "]\n")
