#version 3.7;
#declare F = function { sin(x) + cos(y) + abs(z) + sqrt(4) + pow(2, 3) + exp(0) + ln(1) + log(100) }
#debug concat("F(0, 0, -1) = ", str(F(0, 0, -1), 0, 9), "\n")
