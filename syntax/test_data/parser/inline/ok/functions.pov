#declare F = function { x*x + y*y < 1 & z > 0 }
#declare G = function(a, b, z) { select(a, b, z) + F(a, b, 0) }
#declare P = function { pigment { checker } }
height_field { function 100, 100 { x*y } }
