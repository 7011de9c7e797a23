#version 3.7;
// POV-Ray 3.7 does not take the triangular pattern in a pattern function.
#declare F = function { pattern { triangular } }
#debug str(F(0.3, 0.1, 0.2), 0, 3)
