#version 3.7;
// POV-Ray 3.7 does not take the tiling pattern in a pattern function.
#declare F = function { pattern { tiling 3 } }
#debug str(F(0.3, 0.1, 0.2), 0, 3)
