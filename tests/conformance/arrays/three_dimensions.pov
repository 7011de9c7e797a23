#version 3.7;
#declare C = array[2][2][2] { { {1, 2}, {3, 4} }, { {5, 6}, {7, 8} } };
#debug concat("C[1][0][1] = ", str(C[1][0][1], 0, 0), "\n")
#debug concat("C[0][1][0] = ", str(C[0][1][0], 0, 0), "\n")
