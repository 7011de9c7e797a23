#version 3.7;
#debug concat("concat(\"a\", \"b\", \"c\", \"d\", \"e\", \"f\") = [", concat("a", "b", "c", "d", "e", "f"), "]\n")
