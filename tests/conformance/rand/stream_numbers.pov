#version 3.7;
#declare A = seed(10);
#declare B = seed(20);
#declare C = seed(10);
#debug concat("A = ", str(A, 0, 0), "\n")
#debug concat("B = ", str(B, 0, 0), "\n")
#debug concat("C = ", str(C, 0, 0), "\n")
