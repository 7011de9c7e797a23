#version 3.7;
#debug concat("str(0, 0, 3) = [", str(0, 0, 3), "]\n")
#debug concat("str(0, -5, 0) = [", str(0, -5, 0), "]\n")
#debug concat("str(0, 5, 2) = [", str(0, 5, 2), "]\n")
