#version 3.7;
#debug concat("substr(\"ABCDEFGHI\", 4, 2) = [", substr("ABCDEFGHI", 4, 2), "]\n")
#debug concat("substr(\"ABCDEFGHI\", 1, 9) = [", substr("ABCDEFGHI", 1, 9), "]\n")
#debug concat("substr(\"ABCDEFGHI\", 9, 1) = [", substr("ABCDEFGHI", 9, 1), "]\n")
