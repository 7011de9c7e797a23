#version 3.7;
// A pattern function cannot take slope, which needs a surface.
#declare F = function { pattern { slope y } }
#debug str(F(0, 0, 0), 0, 3)
