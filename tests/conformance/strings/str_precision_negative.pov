#version 3.7;
#debug concat("str(123.456, 0, -1) = [", str(123.456, 0, -1), "]\n")
#debug concat("str(1, 0, -1) = [", str(1, 0, -1), "]\n")
#debug concat("str(-0.5, 0, -1) = [", str(-0.5, 0, -1), "]\n")
#debug concat("str(pi, 0, -3) = [", str(pi, 0, -3), "]\n")
