#version 3.7;
#fopen F "signed.txt" read
#read (F, A, B, C)
#debug concat("A = ", str(A, 0, 3), "\n")
#debug concat("B = ", str(B, 0, 6), "\n")
#debug concat("C = ", str(C, 0, 3), "\n")
