// clipped_by fidelity: a sphere cut open by a box (its inside showing), a plane clipped to
// a disc by a sphere, and a CSG union clipped by an inverted cylinder.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.3, 0.35, 0.45> }
camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { rgb 0.7 } }
sphere { <-3, 0.3, 0>, 1.3 clipped_by { box { <-5, -1, -5>, <5, 0.8, 0.2> } }
  pigment { rgb <0.9, 0.4, 0.2> } finish { specular 0.5 } }
plane { z, 0 clipped_by { sphere { <0, 0.3, 0>, 1.2 } } pigment { rgb <0.3, 0.7, 0.9> } }
union { sphere { <2.6, 0.3, 0>, 1 } box { <2.6, -0.7, -1>, <3.8, 1.3, 1> }
  clipped_by { cylinder { <3, 0.3, -3>, <3, 0.3, 3>, 0.5 inverse } }
  pigment { rgb <0.4, 0.8, 0.3> } }
