// Lathe fidelity: one lathe per spline kind (linear, quadratic, cubic, bezier), with a
// thick-walled tube seen through its opening. S scales the whole scene (the extremes
// test renders it at 1e-5 and 1e5).
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 3.5, -9>*S look_at <0, 0.6, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.5*S pigment { rgb 0.7 } }
lathe { linear_spline 5, <0.4, 0>, <0.8, 0>, <0.8, 1.6>, <0.4, 1.6>, <0.4, 0>
  translate <-3, -0.5, 1> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
lathe { quadratic_spline 6, <0, -0.5>, <0, 0>, <0.9, 0.3>, <0.3, 1.0>, <0.6, 1.6>, <0, 2.0>
  translate <-1, -0.5, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
lathe { cubic_spline 7, <0, -0.3>, <0, 0>, <0.8, 0.2>, <0.4, 0.9>, <0.7, 1.5>, <0, 1.8>, <-0.2, 2>
  translate <1, -0.5, 0> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
lathe { bezier_spline 8, <0, 0>, <1.2, 0>, <0.2, 0.8>, <0.5, 1.2>, <0.5, 1.2>, <0.8, 1.6>, <0.4, 1.8>, <0, 1.8>
  sturm translate <3, -0.5, 1> scale S pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
