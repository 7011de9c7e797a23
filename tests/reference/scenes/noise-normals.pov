// Noise fidelity for normals and agate: the bump patterns that push the normal by POV-Ray's
// vector noise (bumps, dents, wrinkles), a pattern sampled around the point (granite), and
// agate both as bumps and as a pigment, with a turbulence warp and fewer octaves. The noise
// is POV-Ray's, value for value, so the pictures should agree pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 12*x up 8*y }
light_source { <-8, 6, -10> color rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.05 }
#macro Ball(X, Y, N)
  sphere { <X, Y, 0>, 1.7 pigment { rgb <0.8, 0.75, 0.6> } normal { N } finish { F } }
#end
Ball(-4, 2, normal { bumps 0.8 scale 0.3 })
Ball( 0, 2, normal { dents 1.5 scale 0.4 })
Ball( 4, 2, normal { wrinkles 0.9 scale 0.5 })
Ball(-4, -2, normal { granite 0.4 scale 1.5 })
Ball( 0, -2, normal { agate 0.6 scale 0.8 })
sphere { <4, -2, 0>, 1.7
  pigment { agate agate_turb 0.7 octaves 4 turbulence 0.2
    color_map { [0 rgb <0.9, 0.8, 0.6>] [0.5 rgb <0.6, 0.3, 0.2>] [1 rgb <0.2, 0.1, 0.1>] } scale 0.7 }
  finish { F } }
