#version 3.7;
#fopen Out "appended.txt" write
#write (Out, "1,")
#fclose Out
#fopen Out "appended.txt" append
#write (Out, "2")
#fclose Out
#fopen In "appended.txt" read
#read (In, A, B)
#debug concat("A + B = ", str(A + B, 0, 0), "\n")
