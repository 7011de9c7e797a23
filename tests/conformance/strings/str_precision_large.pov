#version 3.7;
#debug concat("str(0.1, 0, 25) = [", str(0.1, 0, 25), "]\n")
#debug concat("str(1/3, 0, 17) = [", str(1/3, 0, 17), "]\n")
