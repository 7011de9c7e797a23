// Parametric fidelity: a sphere from the manual's example (with precompute) and a
// twisted band, both at the default accuracy, with gradients high enough that no hole shows.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 3, -7>*S look_at <0, 0.3, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -1.2*S pigment { rgb 0.7 } }
parametric {
  function { sin(u)*cos(v) }
  function { sin(u)*sin(v) }
  function { cos(u) }
  <0, 0>, <pi, 2*pi>
  contained_by { sphere { 0, 1.1 } }
  max_gradient 1.5
  accuracy 0.001
  precompute 10 x, y, z
  translate <-1.5, 0, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
parametric {
  function { (1 + 0.4*v*cos(u/2))*cos(u) }
  function { 0.4*v*sin(u/2) }
  function { (1 + 0.4*v*cos(u/2))*sin(u) }
  <0, -1>, <2*pi, 1>
  contained_by { box { <-1.5, -0.5, -1.5>, <1.5, 0.5, 1.5> } }
  max_gradient 1.5
  accuracy 0.001
  rotate x*-30 translate <1.4, 0, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
