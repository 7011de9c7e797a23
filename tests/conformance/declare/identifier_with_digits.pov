#version 3.7;
#declare A1_b2 = 3;
#declare _x = 4;
#debug concat("A1_b2 + _x = ", str(A1_b2 + _x, 0, 0), "\n")
