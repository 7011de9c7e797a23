#version 3.7;
#declare A = (1 < 2);
#declare B = (2 = 3) + (4 > 3);
#debug concat("A = ", str(A, 0, 0), "\n")
#debug concat("B = ", str(B, 0, 0), "\n")
