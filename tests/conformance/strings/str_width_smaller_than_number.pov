#version 3.7;
#debug concat("str(123456.5, 3, 1) = [", str(123456.5, 3, 1), "]\n")
#debug concat("str(-99, 1, 0) = [", str(-99, 1, 0), "]\n")
