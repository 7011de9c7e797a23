// Noise fidelity for the cell patterns: cells, crackle (its default form, solid, metric 1
// with an offset) and the facets normal. Each unit cube's random numbers are POV-Ray's,
// value for value, so the pictures should agree pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 12*x up 8*y }
light_source { <-8, 6, -10> color rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.3 roughness 0.05 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.5>] [0.5 rgb <0.9, 0.8, 0.5>] [1 rgb <0.6, 0.1, 0.1>] }
#macro Ball(X, Y, T)
  sphere { <X, Y, 0>, 1.7 texture { T finish { F } } }
#end
Ball(-4, 2, texture { pigment { cells color_map { Map } scale 0.4 } })
Ball( 0, 2, texture { pigment { crackle color_map { Map } scale 0.6 } })
Ball( 4, 2, texture { pigment { crackle solid color_map { Map } scale 0.5 } })
Ball(-4, -2, texture { pigment { crackle metric 1 offset 0.2 form <1, 0, 0> color_map { Map } scale 0.7 } })
Ball( 0, -2, texture { pigment { rgb <0.8, 0.75, 0.6> } normal { crackle 0.8 scale 0.5 } })
Ball( 4, -2, texture { pigment { rgb <0.8, 0.75, 0.6> } normal { facets coords 0.6 size 0.3 } })
