#version 3.7;
#fopen Out "floats.txt" write
#write (Out, 1/3, ",", -2, ",", 1e-7, ",", 123456789)
#fclose Out
#fopen In "floats.txt" read
#read (In, A, B, C, D)
#debug concat("A = ", str(A, 0, 12), "\n")
#debug concat("B = ", str(B, 0, 3), "\n")
#debug concat("C = ", str(C, 0, 12), "\n")
#debug concat("D = ", str(D, 0, 1), "\n")
