#version 3.7;
#fopen F "values.txt" read
#debug concat("defined(F) = ", str(defined(F), 0, 0), "\n")
#fclose F
#debug concat("defined(F) = ", str(defined(F), 0, 0), "\n")
