#version 3.7;
#macro Square(A) (A * A) #end
#debug concat("Square(7) = ", str(Square(7), 0, 0), "\n")
#debug concat("Square(2) + Square(3) = ", str(Square(2) + Square(3), 0, 0), "\n")
