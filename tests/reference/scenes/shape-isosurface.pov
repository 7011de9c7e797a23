// Isosurface extremes: a sphere whose function's gradient (about 30) far exceeds its
// max_gradient of 1, drawn with the holes POV-Ray draws, beside a well-set one and an open
// one cut by its container.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 2, -8>*S look_at <0, 0, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -1.2*S pigment { rgb 0.7 } }
isosurface { function { 15*(x*x + y*y + z*z) - 15 + 0.3*sin(12*x)*sin(12*y) }
  max_gradient 1 contained_by { box { -1.2, 1.2 } }
  translate <-2.4, 0, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
isosurface { function { 15*(x*x + y*y + z*z) - 15 + 0.3*sin(12*x)*sin(12*y) }
  max_gradient 40 contained_by { box { -1.2, 1.2 } }
  translate <0, 0, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
isosurface { function { x*x + y*y + z*z - 1 } open contained_by { box { -0.8, 0.8 } }
  rotate <20, 30, 0> translate <2.4, 0, 0> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
