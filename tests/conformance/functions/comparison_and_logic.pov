#version 3.7;
#declare F = function { (x < y) + (x = y) * 10 + (x > y & y > 0) * 100 + (x | z) * 1000 }
#debug concat("F(1, 2, 0) = ", str(F(1, 2, 0), 0, 0), "\n")
#debug concat("F(2, 2, 0) = ", str(F(2, 2, 0), 0, 0), "\n")
#debug concat("F(3, 2, 0) = ", str(F(3, 2, 0), 0, 0), "\n")
#debug concat("F(0, 0, 0) = ", str(F(0, 0, 0), 0, 0), "\n")
