// quadric: an ellipsoid, a hyperboloid of one sheet clipped to a box, a paraboloid
// bounded by a sphere, and a transformed cylinder clipped by planes, from the manual's
// coefficient form A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0.
// Everything scales with S (the tests render it at 1e-5 and 1e5 too).
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.3, 0.4, 0.55> }
camera { location <0, 3, -10>*S look_at <0, 0.4, 0>*S angle 45 }
light_source { <-5, 10, -8>*S color rgb 1 }
light_source { <6, 4, -6>*S color rgb 0.4 }
plane { y, -1.2*S pigment { checker rgb 0.85, rgb 0.55 scale S } }
quadric { <1, 4, 2>, <0, 0, 0>, <0, 0, 0>, -1
  translate <-3, 0, 0> scale S pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.6 } }
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.3
  clipped_by { box { <-1.2, -1.1, -1.2>, <1.2, 1.1, 1.2> } }
  translate <-0.6, 0, 1> scale S pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.5 } }
quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, -0.5
  bounded_by { sphere { 0, 1.5 } } clipped_by { bounded_by }
  rotate x*20 translate <1.8, -0.2, 0> scale S pigment { rgb <0.35, 0.5, 0.95> } }
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.25
  clipped_by { plane { y, 1.2 } plane { -y, 1 } }
  rotate z*30 rotate y*-20 translate <3.6, 0, 2> scale S pigment { rgb <0.9, 0.8, 0.3> } }
