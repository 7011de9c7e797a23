// Ground fog (fog_type 2) of its own: dense up to fog_offset, thinning above it over
// fog_alt along a tilted up direction, with a little filter, over a checkered floor among
// pillars at several distances; the sky above the fog shows the background.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -7> look_at <0, 0.8, 0> angle 65 }
light_source { <-15, 25, -20> rgb 1 }
background { rgb <0.25, 0.35, 0.6> }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.75> rgb <0.15, 0.25, 0.15> } }
#declare Pillar = cylinder { 0, 3*y, 0.3 pigment { rgb <0.8, 0.3, 0.2> } finish { specular 0.3 } }
object { Pillar translate <-2.5, 0, -2> }
object { Pillar translate <2, 0, 1> }
object { Pillar translate <-1, 0, 5> }
object { Pillar translate <3.5, 0, 9> }
object { Pillar translate <-4, 0, 14> }
sphere { <0.3, 0.6, -3>, 0.6 pigment { rgb <0.2, 0.4, 0.9> } finish { specular 0.5 } }
fog {
  fog_type 2
  distance 4
  color rgbf <0.85, 0.88, 0.95, 0.2>
  fog_offset 0.4
  fog_alt 0.7
  up <0.15, 1, 0>
}
