#version 3.7;
#fopen F "strings.txt" read
#read (F, A, B)
#debug concat("concat(A, \"+\", B) = [", concat(A, "+", B), "]\n")
