#version 3.7;
#declare F = function { pattern { leopard } }
#debug concat("F(0.1, 0.2, 0.3) = ", str(F(0.1, 0.2, 0.3), 0, 9), "\n")
#debug concat("F(0.5, 0.5, 0.5) = ", str(F(0.5, 0.5, 0.5), 0, 9), "\n")
