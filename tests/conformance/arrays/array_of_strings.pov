#version 3.7;
#declare S = array[3] {"alpha", "beta", "gamma"};
#debug concat("concat(S[2], \"/\", S[0]) = [", concat(S[2], "/", S[0]), "]\n")
