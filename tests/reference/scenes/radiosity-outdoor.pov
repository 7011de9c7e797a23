// Outdoors under a blue sky, a dome that glows, and a low sun: the shadows take the sky's
// blue and the ground's green by radiosity.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 80 error_bound 1.2 recursion_limit 1 pretrace_end 0.02 }
}
camera { location <0, 2.2, -8> look_at <0, 1, 0> angle 50 }
light_source { <30, 40, -25> rgb <1, 0.95, 0.85> * 1.3 }
sphere { 0, 500 hollow
  pigment { gradient y color_map { [0 rgb <0.75, 0.85, 1>] [0.4 rgb <0.3, 0.5, 0.95>] } scale 500 }
  finish { emission 0.9 diffuse 0 }
  no_shadow }
plane { y, 0 pigment { rgb <0.35, 0.55, 0.25> } finish { diffuse 0.8 } }
box { <-1, 0, -1>, <1, 2, 1> rotate y * 30 translate <-1.8, 0, 1> pigment { rgb 0.85 } finish { diffuse 0.8 } }
sphere { <1.6, 1, -0.5>, 1 pigment { rgb <0.9, 0.75, 0.4> } finish { diffuse 0.8 } }
cylinder { <0.3, 0, 2.5>, <0.3, 3, 2.5>, 0.35 pigment { rgb <0.8, 0.3, 0.25> } finish { diffuse 0.8 } }
