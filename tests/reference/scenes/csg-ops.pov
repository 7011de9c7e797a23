// CSG fidelity: union, merge, intersection, difference, inverse and nesting, in a row.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.2, 0.25, 0.3> }
camera { location <0, 4, -10> look_at <0, 0, 0> angle 45 }
light_source { <-4, 8, -7> color rgb 1.2 }
plane { y, -1.2 pigment { rgb 0.6 } }
#declare A = sphere { <-0.35, 0, 0>, 0.8 }
#declare B = sphere { < 0.35, 0, 0>, 0.8 }
union        { object { A } object { B } translate <-4.5, 0, 0> pigment { rgb <0.9, 0.4, 0.3> } }
merge        { object { A } object { B } translate <-2.2, 0, 0> pigment { rgb <0.3, 0.8, 0.4> } }
intersection { object { A } object { B } translate < 0, 0, 0> pigment { rgb <0.3, 0.5, 0.9> } }
difference   { object { A } object { B } translate < 2.2, 0, 0> pigment { rgb <0.9, 0.8, 0.3> } }
intersection {
  box { -0.8, 0.8 }
  object { B inverse }
  difference { sphere { 0, 1.05 } cylinder { -2*z, 2*z, 0.4 } }
  rotate y*-30 translate <4.5, 0, 0> pigment { rgb <0.8, 0.4, 0.9> }
}
