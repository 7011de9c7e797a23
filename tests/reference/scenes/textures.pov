// Texture fidelity: layered textures showing through their filter and transmit, and a
// pigment_map nesting a checker pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.4, 0.5, 0.6> }
camera { location <0, 3, -9> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.85, 0.7>, rgb <0.2, 0.3, 0.5> } }
sphere { <-3, 0.5, 0>, 1.4
  texture { pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.9 } }
  texture { pigment { gradient y color_map { [0.5 rgbt <0, 0, 1, 0.2>] [0.5 rgbt 1] } scale 0.4 } } }
sphere { <0, 0.5, 0>, 1.4
  texture { pigment { rgb <0.2, 0.7, 0.3> } }
  texture { pigment { gradient x color_map { [0.5 rgbt <1, 1, 1, 1>] [0.5 rgbf <1, 0.9, 0.2, 0.4>] } scale 0.5 }
            finish { specular 0.6 } } }
sphere { <3, 0.5, 0>, 1.4
  pigment { spherical pigment_map { [0 checker rgb 1, rgb 0 scale 0.2] [1 rgb <0.9, 0.5, 0.1>] } scale 1.4 translate <3, 0.5, 0> } }
