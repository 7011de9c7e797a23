#version 3.7;
#debug "before\n"
#debug concat("concat(\"a\", 5) = [", concat("a", 5), "]\n")
