#version 3.7;
#debug concat("datetime(0) = [", datetime(0), "]\n")
#debug concat("datetime(1.5) = [", datetime(1.5), "]\n")
#debug concat("datetime(-1) = [", datetime(-1), "]\n")
