#version 3.7;
#declare A = array[6];
#declare B = array[6][10];
#declare C = array[2][3][4];
#debug concat("dimensions(A) = ", str(dimensions(A), 0, 0), "\n")
#debug concat("dimensions(B) = ", str(dimensions(B), 0, 0), "\n")
#debug concat("dimensions(C) = ", str(dimensions(C), 0, 0), "\n")
