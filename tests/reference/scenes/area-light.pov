// Area light fidelity: soft shadows from a 5x5 adaptive area light without jitter.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.2, 0.3, 0.4> }
camera { location <0, 5, -8> look_at <0, 0.5, 0> angle 45 }
plane { y, 0 pigment { rgb 0.85 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
box { <1.8, 0, -0.5>, <2.8, 2, 0.5> pigment { rgb <0.3, 0.6, 0.9> } }
light_source { <-3, 7, -2> color rgb 1
  area_light <3, 0, 0>, <0, 0, 3>, 5, 5 adaptive 1 }
