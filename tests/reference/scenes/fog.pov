// Constant fog over a checkered floor, with a ground fog layered on it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 0> angle 60 }
light_source { <-20, 30, -20> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.2> scale 2 } }
sphere { <-2, 1, 2>, 1 pigment { rgb <0.9, 0.2, 0.1> } finish { specular 0.4 } }
sphere { <2.5, 1.5, 8>, 1.5 pigment { rgb <0.1, 0.4, 0.9> } }
box { <-1, 0, 14>, <1, 6, 16> pigment { rgb <0.9, 0.8, 0.2> } }
fog { distance 30 rgbf <0.7, 0.75, 0.8, 0.2> }
fog { fog_type 2 distance 4 rgbt <0.9, 0.9, 1, 0.1> fog_offset 0.3 fog_alt 0.6 }
