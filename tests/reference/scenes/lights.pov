// Light fidelity: a spotlight, a cylinder light, a parallel light and a fading point light
// on a floor with posts that cast shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.05 }
camera { location <0, 9, -11> look_at <0, 0, 0> angle 55 }
plane { y, 0 pigment { rgb 0.8 } }
#declare Post = cylinder { 0, y*1.5, 0.25 pigment { rgb <0.9, 0.9, 0.6> } }
object { Post translate <-4, 0, 2> }
object { Post translate <0, 0, 2> }
object { Post translate <4, 0, 2> }
object { Post translate <0, 0, -3> }
light_source { <-4, 6, 0> color rgb <1, 0.6, 0.3>
  spotlight point_at <-4, 0, 2> radius 15 falloff 30 tightness 5 }
light_source { <4, 6, -2> color rgb <0.3, 0.6, 1>
  cylinder point_at <4, 0, 2> radius 1.2 falloff 2 tightness 1 }
light_source { <0, 20, -20> color rgb 0.25 parallel point_at <0, 0, 0> }
light_source { <0, 3, -3> color rgb <0.6, 1, 0.6> fade_distance 2 fade_power 2 }
