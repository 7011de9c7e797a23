#version 3.7;
#declare K = 3;
#declare A = array[3] {K, K * 2, K * K};
#debug concat("A[0] + A[1] + A[2] = ", str(A[0] + A[1] + A[2], 0, 0), "\n")
