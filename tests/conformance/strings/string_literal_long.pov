#version 3.7;
#declare S = "0123456789012345678901234567890123456789012345678901234567890123";
#debug concat("strlen(S) = ", str(strlen(S), 0, 0), "\n")
