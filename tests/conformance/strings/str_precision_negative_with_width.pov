#version 3.7;
#debug concat("str(pi, 12, -1) = [", str(pi, 12, -1), "]\n")
#debug concat("str(pi, -12, -1) = [", str(pi, -12, -1), "]\n")
