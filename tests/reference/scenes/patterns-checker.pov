// Pattern fidelity: checker on a plane and a sphere, with pigments nested in the checker.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.8> }
camera { location <0, 3, -6> look_at <0, 0, 1> angle 55 }
light_source { <3, 8, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.9, 0.85>, rgb <0.2, 0.25, 0.3> } }
sphere { <0, 0.2, 1>, 1.2
  pigment { checker pigment { gradient y color_map { [0 rgb <1, 0.3, 0>] [1 rgb <1, 1, 0>] } },
                    pigment { rgb <0.1, 0.5, 0.2> } scale 0.5 }
  finish { phong 0.5 } }
