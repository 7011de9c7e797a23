#version 3.7;
#debug concat("concat(\"ab\", \"cd\") = [", concat("ab", "cd"), "]\n")
