#version 3.7;
#include "colors.inc"
#default { finish { ambient 0.1 } }
#undef Foo
#debug concat("x = ", str(X, 0, 2), "\n")
#warning "careful"
#fopen F "data.txt" read
#read (F, A, B)
#write (F, A, ",", B, "\n")
#write (F, uint16be <X, Y, Z>, sint8 -1)
#fclose F
