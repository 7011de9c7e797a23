#version 3.7;
#fopen Out "written.txt" write
#write (Out, "\"text\",", 3.25, ",", <1, 2, 3>, "\n")
#fclose Out
#fopen In "written.txt" read
#read (In, S, F, V)
#fclose In
#debug concat("S = [", S, "]\n")
#debug concat("F = ", str(F, 0, 3), "\n")
#debug concat("V = <", vstr(3, V, ", ", 0, 1), ">\n")
