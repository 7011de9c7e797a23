#version 3.7;
// POV-Ray 3.7 does not take the pavement pattern in a pattern function.
#declare F = function { pattern { pavement } }
#debug str(F(0.3, 0.1, 0.2), 0, 3)
