// Ripples and waves: as pigments (top row, with frequency and phase) and as normals
// (bottom row, their own bump functions), lit from one side so that the tilt shows. Their
// ten wave sources are POV-Ray's (analysis/src/pattern/waves.rs), so the rings must sit
// where POV-Ray's sit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 12*x up 8*y }
light_source { <-8, 6, -10> color rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.05 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 0.8>] [1 rgb <0.6, 0.2, 0.1>] }
box { <-5.8, 0.2, 0>, <-2.2, 3.8, 1> pigment { ripples color_map { Map } scale 0.5 } finish { ambient 1 diffuse 0 } }
box { <-1.8, 0.2, 0>, <1.8, 3.8, 1> pigment { ripples frequency 2.5 phase 0.3 color_map { Map } } finish { ambient 1 diffuse 0 } }
box { <2.2, 0.2, 0>, <5.8, 3.8, 1> pigment { waves frequency 3 color_map { Map } scale 0.7 } finish { ambient 1 diffuse 0 } }
#macro Ball(X, Y, N)
  sphere { <X, Y, 0>, 1.7 pigment { rgb <0.8, 0.75, 0.6> } normal { N } finish { F } }
#end
Ball(-4, -2, normal { ripples 0.8 scale 0.6 })
Ball( 0, -2, normal { waves 0.6 frequency 2 scale 0.5 })
Ball( 4, -2, normal { ripples 1.0 frequency 3 phase 0.25 translate <0.3, 0, 0> })
