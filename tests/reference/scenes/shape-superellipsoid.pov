// Superellipsoid fidelity: a rounded box, a rounded cylinder, a sphere, and pinched shapes
// with exponents above 2.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 4, -8>*S look_at <0, 0.3, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.8*S pigment { rgb 0.7 } }
superellipsoid { <0.2, 0.2> scale 0.6 rotate <10, 30, 0> translate <-2.6, 0, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
superellipsoid { <1, 0.3> scale 0.6 rotate x*-70 translate <-0.9, 0, 0.3> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
superellipsoid { <1, 1> scale 0.6 translate <0.8, 0, 0> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
superellipsoid { <2.5, 2.5> scale 0.8 rotate <20, 20, 0> translate <2.6, 0, 0> scale S pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
superellipsoid { <0.5, 3> scale 0.6 rotate y*30 translate <0, 0, -2> scale S pigment { rgb <0.8, 0.5, 0.9> } finish { F } }
