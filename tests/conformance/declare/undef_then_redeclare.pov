#version 3.7;
#declare A = 1;
#undef A
#declare A = "text";
#debug concat("A = [", A, "]\n")
