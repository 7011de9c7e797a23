#version 3.7;
#debug "before\n"
#debug concat("substr(\"ABC\", 0, 2) = [", substr("ABC", 0, 2), "]\n")
