#version 3.7;
#fopen Out "vectors.txt" write
#write (Out, <1/3, -0.5, 2>, ",", <1, 2>)
#fclose Out
#fopen In "vectors.txt" read
#read (In, A, B)
#debug concat("A = <", vstr(3, A, ", ", 0, 9), ">\n")
#debug concat("B = <", vstr(3, B, ", ", 0, 3), ">\n")
