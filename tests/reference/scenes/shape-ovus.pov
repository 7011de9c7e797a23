// Ovus fidelity: an egg, its upturned twin, a nearly round one and the degenerate case
// (top radius at least twice the bottom: a sphere).
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 3, -8>*S look_at <0, 0.6, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.6*S pigment { rgb 0.7 } }
ovus { 0.6, 0.3 translate <-2.4, 0, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
ovus { 0.3, 0.55 translate <-0.8, -0.25, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
ovus { 0.5, 0.45 rotate z*60 translate <0.9, 0.2, 0> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
ovus { 0.25, 0.6 translate <2.6, -0.1, 0> scale S pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
