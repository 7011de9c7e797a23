// Pattern fidelity: pavement's corner looks with triangle cells (exterior for their points of
// 60 degrees, form for their corners of 120, interior for their notches and for
// straight edges across a cell's corner; 0 sharp, 1 cut, 2 round), each on a box face with the
// pattern's x-z plane turned to face the camera, and a colour map that shows the ramp
// from the tiles' edges (1) to their insides (0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 16*x up 12*y }
light_source { <0, 0, -100> color rgb 1 }
#declare M = color_map {
  [0 rgb <0.1, 0.2, 0.5>] [0.4 rgb <0.2, 0.6, 0.4>] [0.8 rgb <0.95, 0.85, 0.4>] [1 rgb <0.9, 0.2, 0.1>]
}
#declare F = finish { ambient 0.3 diffuse 0.7 }
#macro Tile(X, Y, T, P, Fo, E, I, S)
  box { <-1.9, -1.9, 0>, <1.9, 1.9, 1>
    pigment { pavement number_of_sides 3 number_of_tiles T pattern P
      form Fo exterior E interior I color_map { M }
      scale S rotate x*-90 translate <0.13, 0.07, 0> }
    finish { F } translate <X, Y, 0> }
#end
Tile(-6,  4, 1,  1, 0, 1, 0, 0.6)
Tile(-2,  4, 1,  1, 0, 2, 0, 0.6)
Tile( 2,  4, 6, 12, 1, 0, 0, 0.35)
Tile( 6,  4, 6, 12, 2, 0, 0, 0.35)
Tile(-6,  0, 4,  2, 1, 2, 1, 0.35)
Tile(-2,  0, 4,  3, 0, 0, 2, 0.35)
Tile( 2,  0, 5,  4, 0, 2, 1, 0.3)
Tile( 6,  0, 3,  1, 1, 2, 2, 0.35)
Tile(-6, -4, 6, 11, 2, 1, 1, 0.3)
Tile(-2, -4, 6,  5, 2, 1, 2, 0.3)
Tile( 2, -4, 6,  1, 1, 1, 0, 0.3)
Tile( 6, -4, 5,  2, 2, 2, 2, 0.3)
