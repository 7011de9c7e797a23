// Pattern fidelity: the tiling patterns 1 to 12, each on a box face, the tiling's
// x-z plane turned to face the camera, with a colour map that shows every value band.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 16*x up 12*y }
light_source { <0, 0, -100> color rgb 1 }
#declare M = color_map {
  [0 rgb <0.9, 0.2, 0.1>] [0.3 rgb <0.95, 0.95, 0.3>] [0.6 rgb <0.1, 0.6, 0.3>] [1 rgb <0.1, 0.3, 0.9>]
}
#declare F = finish { ambient 0.3 diffuse 0.7 }
#macro Tile(X, Y, N, S)
  box { <-1.9, -1.9, 0>, <1.9, 1.9, 1>
    pigment { tiling N color_map { M } scale S rotate x*-90 translate <0.2, 0.1, 0> }
    finish { F } translate <X, Y, 0> }
#end
Tile(-6,  4,  1, 0.7)
Tile(-2,  4,  2, 0.5)
Tile( 2,  4,  3, 0.7)
Tile( 6,  4,  4, 0.6)
Tile(-6,  0,  5, 0.5)
Tile(-2,  0,  6, 0.5)
Tile( 2,  0,  7, 0.4)
Tile( 6,  0,  8, 0.6)
Tile(-6, -4,  9, 0.5)
Tile(-2, -4, 10, 0.6)
Tile( 2, -4, 11, 0.4)
Tile( 6, -4, 12, 0.35)
