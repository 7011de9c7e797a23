#version 3.7;
#debug concat("str(-1.5, -3, 2) = [", str(-1.5, -3, 2), "]\n")
#debug concat("str(-1.5, -8, 2) = [", str(-1.5, -8, 2), "]\n")
#debug concat("str(-1.5, 8, 2) = [", str(-1.5, 8, 2), "]\n")
