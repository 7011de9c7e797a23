// Pattern fidelity: blend patterns with colour maps, frequency, phase and wave types.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 16*x up 12*y }
light_source { <0, 0, -100> color rgb 1 }
#declare M = color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <0.95, 0.95, 0.3>] [1 rgb <0.1, 0.3, 0.9>] }
#declare F = finish { ambient 0.3 diffuse 0.7 }
#macro Tile(X, Y, P)
  box { <-1.9, -1.9, 0>, <1.9, 1.9, 1> pigment { P } finish { F } translate <X, Y, 0> }
#end
Tile(-6, 4, pigment { gradient x color_map { M } scale 2 translate -x })
Tile(-2, 4, pigment { gradient <1, 1, 0> color_map { M } frequency 2 phase 0.25 })
Tile( 2, 4, pigment { spherical color_map { M } scale 1.8 })
Tile( 6, 4, pigment { onion color_map { M } scale 0.6 })
Tile(-6, 0, pigment { radial color_map { M } frequency 3 rotate x*-90 })
Tile(-2, 0, pigment { boxed color_map { M } scale 1.5 })
Tile( 2, 0, pigment { planar color_map { M } scale 1.5 })
Tile( 6, 0, pigment { cylindrical color_map { M } rotate x*90 scale 1.5 })
Tile(-6, -4, pigment { leopard color_map { M } scale 0.2 })
Tile(-2, -4, pigment { marble color_map { M } scale 1.5 })
Tile( 2, -4, pigment { wood color_map { M } scale 0.5 })
Tile( 6, -4, pigment { gradient y color_map { M } sine_wave scale 1.5 })
