// Julia fractal extremes: one iteration (a smooth blob), the usual twenty, and two hundred.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 2, -8>*S look_at <0, 0, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -1.5*S pigment { rgb 0.7 } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 1 precision 20
  translate <-2.6, 0, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 20 precision 20
  translate <0, 0, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 200 precision 20
  translate <2.6, 0, 0> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
