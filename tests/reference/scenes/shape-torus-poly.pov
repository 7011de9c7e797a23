// Torus and polynomial extremes: a torus seen exactly edge-on (rays grazing its tube meet
// double roots along the silhouette), a spindle torus, a rounded cube of degree four with sturm and a thin
// torus nearly tangent to the view.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 0, -9>*S look_at <0, 0, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -1.6*S pigment { rgb 0.7 } }
torus { 1, 0.35 translate <-2.3, 0.8, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
torus { 0.5, 0.7 rotate x*-60 translate <0.3, 0.8, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
torus { 1.2, 0.02 rotate x*-88 translate <2.5, 0.8, 0> scale S pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
quartic { < 1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            1, 0, 0, 0, -1 >
  sturm bounded_by { box { -1.1, 1.1 } } scale 0.6 rotate <30, 20, 0> translate <-1.2, -0.8, -0.5> scale S
  pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
