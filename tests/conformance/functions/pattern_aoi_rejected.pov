#version 3.7;
// A pattern function cannot take aoi, which needs a surface.
#declare F = function { pattern { aoi } }
#debug str(F(0, 0, 0), 0, 3)
