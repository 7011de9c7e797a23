#version 3.7;
#declare A = array[1] {<4, 5, 6>};
#debug concat("A[0].z = ", str(A[0].z, 0, 0), "\n")
