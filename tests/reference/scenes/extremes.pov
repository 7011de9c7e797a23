// Robustness fidelity: the whole scene scales with S (the tests render it at 1e-6 and 1e6
// too), with a floor seen at a grazing angle, two boxes sharing a face, a sphere touching
// the floor and a thin disc lying on it.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.7> }
camera { location <0, 0.3, -8>*S look_at <0, 0.3, 0>*S angle 50 }
light_source { <-4, 6, -5>*S color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 scale S } }
box { <-2.5, 0, 0>*S, <-1, 1.5, 1.5>*S pigment { rgb <0.9, 0.3, 0.2> } }
box { <-1, 0, 0>*S, <0.5, 1, 1.5>*S pigment { rgb <0.2, 0.6, 0.9> } }
sphere { <2, 1, 0>*S, 1*S pigment { rgb <0.3, 0.8, 0.3> } finish { specular 0.5 } }
disc { <0, 0, -2>*S, y, 0.8*S pigment { rgb <1, 0.9, 0.2> } }
