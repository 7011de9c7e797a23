#version 3.7;
#declare F = function { x }
#undef F
#declare F = function { y }
#debug concat("F(1, 2, 3) = ", str(F(1, 2, 3), 0, 0), "\n")
