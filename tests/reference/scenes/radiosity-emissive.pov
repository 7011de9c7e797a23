// A closed room lit only by a glowing panel under the ceiling and a glowing orange ball:
// every bit of light on the walls, the floor and the pillar comes by radiosity.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 120 error_bound 1 recursion_limit 2 pretrace_end 0.02 nearest_count 6 }
}
camera { location <-2.6, 1.6, -3.2> look_at <0.2, 1.1, 0> angle 70 }
#declare Plaster = texture { pigment { rgb <0.8, 0.78, 0.72> } finish { diffuse 0.75 } }
box { <-3, 0, -3.5>, <3, 3, 3> inverse texture { Plaster } }
box { <-1, 2.9, -0.6>, <1, 2.99, 0.6> pigment { rgb 1 } finish { emission 4 diffuse 0 } }
sphere { <1.4, 0.45, -0.6>, 0.45 pigment { rgb <1, 0.45, 0.1> } finish { emission 1.5 diffuse 0 } }
box { <-0.5, 0, 0.8>, <0.5, 2.2, 1.8> rotate y * 25 pigment { rgb <0.3, 0.5, 0.8> } finish { diffuse 0.8 } }
box { <-2.99, 0, -2>, <-2.2, 0.9, 0.5> pigment { rgb <0.6, 0.25, 0.2> } finish { diffuse 0.7 } }
