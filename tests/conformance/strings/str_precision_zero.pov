#version 3.7;
#debug concat("str(123.456, 0, 0) = [", str(123.456, 0, 0), "]\n")
#debug concat("str(0.4, 0, 0) = [", str(0.4, 0, 0), "]\n")
#debug concat("str(0.6, 0, 0) = [", str(0.6, 0, 0), "]\n")
#debug concat("str(-0.6, 0, 0) = [", str(-0.6, 0, 0), "]\n")
#debug concat("str(99.5, 0, 0) = [", str(99.5, 0, 0), "]\n")
