#version 3.7;
#declare F = function { sinh(x) + cosh(x) + tanh(x) + asinh(x) + acosh(y) + atanh(z) }
#debug concat("F(0.5, 2, 0.25) = ", str(F(0.5, 2, 0.25), 0, 9), "\n")
