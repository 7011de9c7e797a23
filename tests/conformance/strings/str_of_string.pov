#version 3.7;
#debug "before\n"
#debug concat("str(\"a\", 0, 0) = [", str("a", 0, 0), "]\n")
