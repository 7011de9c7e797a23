// Prism fidelity: linear, quadratic, cubic and bezier outlines (a frame with a hole, a
// rounded star), a conic sweep and an open prism.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 6, -9>*S look_at <0, 0, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.5*S pigment { rgb 0.7 } }
prism { linear_spline 0, 0.8, 10,
  <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale 0.22 translate <-3.8, -0.5, 0.3> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
prism { quadratic_spline 0, 0.6, 12,
  <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale 0.2 translate <-1.3, -0.5, 0.6> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
prism { cubic_spline 0, 1, 14,
  <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <-1,1>, <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>, <0,2>
  scale 0.2 translate <1, -0.5, 0.6> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
prism { bezier_spline -0.5, 0.3, 8,
  <0, 1>, <1, 1>, <1, 0>, <1, -0.2>, <1, -0.2>, <0.2, -1>, <-1, 0.2>, <0, 1>
  sturm translate <3.2, 0, 1> scale S pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
prism { conic_sweep linear_spline 0.3, 1, 5, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1>
  rotate x*180 translate <-2, 0.5, -2> scale S pigment { rgb <0.8, 0.5, 0.9> } finish { F } }
prism { linear_spline 0, 1, 4, <0, 0>, <1, 0>, <0.5, 0.9>, <0, 0> open
  translate <0.8, -0.5, -2.2> scale S pigment { rgb <0.5, 0.9, 0.9> } finish { F } }
