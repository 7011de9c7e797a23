#version 3.7;
#debug concat("str(123.456, 4, 3) = [", str(123.456, 4, 3), "]\n")
#debug concat("str(123.456, 9, 3) = [", str(123.456, 9, 3), "]\n")
#debug concat("str(123.456, 12, 3) = [", str(123.456, 12, 3), "]\n")
