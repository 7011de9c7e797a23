// A still life under a window light, with radiosity from rad_def.inc's Radiosity_Normal
// preset: a table, a vase and a bowl in a corner of a room.
#version 3.7;
#include "rad_def.inc"
global_settings { assumed_gamma 1 radiosity { Rad_Settings(Radiosity_Normal, off, off) } }
camera { location <2.5, 2.2, -4> look_at <-0.2, 0.9, 0.4> angle 55 }
light_source { <3, 3.5, -2> rgb 1.2 area_light x * 0.6, y * 0.6, 3, 3 adaptive 1 }
#declare Wall = texture { pigment { rgb <0.85, 0.82, 0.75> } finish { diffuse 0.8 } }
plane { y, 0 pigment { checker rgb <0.55, 0.35, 0.2>, rgb <0.45, 0.28, 0.16> scale 0.5 } finish { diffuse 0.75 } }
plane { z, 2 texture { Wall } }
plane { x, -2 texture { Wall } }
box { <-1.4, 0.75, -0.6>, <0.8, 0.82, 1.2> pigment { rgb <0.9, 0.88, 0.85> } finish { diffuse 0.8 } }
cylinder { <-0.4, 0.82, 0.5>, <-0.4, 1.6, 0.5>, 0.22 pigment { rgb <0.2, 0.35, 0.8> } finish { diffuse 0.7 specular 0.3 } }
sphere { <0.3, 0.82, -0.1>, 0.3 scale <1, 0.5, 1> translate y * 0.0 pigment { rgb <0.9, 0.5, 0.15> } finish { diffuse 0.8 } }
#declare Leg = box { <-0.05, 0, -0.05>, <0.05, 0.75, 0.05> pigment { rgb 0.4 } }
object { Leg translate <-1.3, 0, -0.5> } object { Leg translate <0.7, 0, -0.5> }
object { Leg translate <-1.3, 0, 1.1> } object { Leg translate <0.7, 0, 1.1> }
