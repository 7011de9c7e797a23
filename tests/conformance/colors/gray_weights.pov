#version 3.7;
#debug concat("(x).gray = ", str((x).gray, 0, 12), "\n")
#debug concat("(y).gray = ", str((y).gray, 0, 12), "\n")
#debug concat("(z).gray = ", str((z).gray, 0, 12), "\n")
