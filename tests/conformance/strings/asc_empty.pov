#version 3.7;
#debug concat("asc(\"\") = ", str(asc(""), 0, 0), "\n")
