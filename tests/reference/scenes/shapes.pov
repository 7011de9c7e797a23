// Shape fidelity: every basic shape, transformed, with specular highlights and shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 9, -6> color rgb 1.1 }
light_source { <6, 4, -3> color rgb 0.4 }
#declare F = finish { specular 0.6 roughness 0.02 }
plane { y, -1 pigment { rgb 0.7 } }
sphere { <-3, 0, 2>, 1 scale <1, 0.6, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
box { -0.7, 0.7 rotate <20, 35, 0> translate <0, -0.1, 2> pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
cylinder { <-0.5, 0, 0>, <0.5, 0, 0>, 0.4 rotate y*30 translate <3, -0.3, 2> pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
cone { <0, -1, 0>, 0.8, <0, 0.6, 0>, 0.2 translate <-3, 0, -1.5> pigment { rgb <0.9, 0.8, 0.2> } finish { F } }
cone { <0, -1, 0>, 0.6, <0, 0.4, 0>, 0.3 open rotate z*-25 translate <-1, 0, -2.5> pigment { rgb <0.8, 0.5, 0.9> } finish { F } }
cylinder { <0, -1, 0>, <0, 0, 0>, 0.5 open translate <1, 0, -2.5> pigment { rgb <0.5, 0.9, 0.9> } finish { F } }
torus { 0.8, 0.25 rotate x*-40 translate <3, 0, -1> pigment { rgb <0.9, 0.5, 0.2> } finish { F } }
disc { <0, 0, 0>, <0, 1, -1>, 0.8, 0.3 translate <0.3, 0, -0.6> pigment { rgb <0.95, 0.95, 0.6> } }
triangle { <-1.5, -1, 3.5>, <0, 1.5, 4>, <1.5, -1, 3.5> pigment { rgb <0.4, 0.6, 0.9> } }
smooth_triangle { <2, -1, 4>, <-1, 0, -1>, <4.5, -1, 4>, <1, 0, -1>, <3.25, 1.2, 4.5>, <0, 1, -1>
  pigment { rgb <0.6, 0.9, 0.5> } finish { F } }
