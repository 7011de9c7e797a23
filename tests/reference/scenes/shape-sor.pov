// Surface of revolution fidelity: a closed vase, an open one seen from above, and one
// turned on its side.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 4, -8>*S look_at <0, 0.5, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.5*S pigment { rgb 0.7 } }
#declare Vase = sor { 7, <0, 0>, <0.5, 0>, <1.2, 0.5>, <0.4, 0.9>, <0.4, 1.3>, <0.6, 1.7>, <0.8, 1.9> }
object { Vase translate <-2.2, -0.5, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
sor { 7, <0, 0>, <0.5, 0>, <1.2, 0.5>, <0.4, 0.9>, <0.4, 1.3>, <0.6, 1.7>, <0.8, 1.9> open
  translate <0.3, -0.5, 0.5> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
sor { 6, <0.2, -0.5>, <0.5, 0>, <0.3, 0.6>, <0.6, 1.2>, <0.2, 1.8>, <0, 2.2> sturm
  rotate z*80 translate <3.2, 0, -0.5> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
