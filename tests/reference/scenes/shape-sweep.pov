// Sphere sweep extremes: one sweep of each kind, with radii varying along them, and a
// linear sweep of radius 1e-4 that must leave no trace but no error either.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 3, -8>*S look_at <0, 0, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -1*S pigment { rgb 0.7 } }
sphere_sweep { linear_spline 4, <-3.5, -0.5, 0>, 0.2, <-2.5, 0.8, 0>, 0.4, <-1.8, -0.3, 0.5>, 0.15, <-1.5, 0.6, 0>, 0.3
  scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
sphere_sweep { b_spline 6, <-1, -0.5, 0>, 0.2, <-0.5, 0.8, 0>, 0.3, <0, -0.5, 0>, 0.2, <0.5, 0.8, 0>, 0.35, <1, -0.5, 0>, 0.2, <1.5, 0.8, 0>, 0.2
  scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
sphere_sweep { cubic_spline 5, <1.5, 0, 0>, 0.2, <2, 0.6, -0.5>, 0.25, <2.8, -0.4, 0>, 0.3, <3.4, 0.5, 0.5>, 0.15, <3.8, 0, 0>, 0.2
  scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
sphere_sweep { linear_spline 2, <-2, -0.9, -1>, 1e-4, <2, -0.9, -1>, 1e-4
  scale S pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
