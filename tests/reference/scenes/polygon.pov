// polygon: sub-polygons closed by repeating their first point, holes where an even number
// of them overlap (the letter P of the manual, and its triangle with three holes and
// three islands).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2, 3, -8> look_at <2, 2.5, 0> }
light_source { <-3, 8, -6> rgb 1 }
polygon { 12,
  <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1,0>, <0, 0>,
  <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4>
  pigment { rgb <1, 0.8, 0.3> } rotate 20*y }
polygon { 28,
  <0, 0> <1, 0> <0, 1> <0, 0>
  <.3, .7> <.4, .7> <.3, .8> <.3, .7>
  <.5, .5> <.6, .5> <.5, .6> <.5, .5>
  <.7, .3> <.8, .3> <.7, .4> <.7, .3>
  <.5, .2> <.6, .2> <.5, .3> <.5, .2>
  <.2, .5> <.3, .5> <.2, .6> <.2, .5>
  <.1, .1> <.2, .1> <.1, .2> <.1, .1>
  pigment { rgb <0.3, 0.6, 1> } scale 3 translate <2.5, 0, -1> }
plane { y, 0 pigment { checker rgb 0.4 rgb 0.7 } }
