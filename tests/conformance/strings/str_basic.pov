#version 3.7;
#debug concat("str(123.456, 0, 3) = [", str(123.456, 0, 3), "]\n")
#debug concat("str(123.456, 0, 2) = [", str(123.456, 0, 2), "]\n")
#debug concat("str(123.456, 0, 1) = [", str(123.456, 0, 1), "]\n")
#debug concat("str(123.456, 0, 0) = [", str(123.456, 0, 0), "]\n")
