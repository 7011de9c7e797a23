#version 3.7;
#declare S = "MiXeD";
#declare U = strupr(S);
#debug concat("S = [", S, "]\n")
#debug concat("U = [", U, "]\n")
