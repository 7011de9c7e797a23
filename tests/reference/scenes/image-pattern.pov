// image_pattern: an image's grey levels choosing colours from a colour map, its alpha
// (use_alpha) blending two textures, and a palette image's grey levels (use_index changes
// nothing in an image pattern).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 4, -6> rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
#declare Leaf = texture { pigment { rgb <0.2, 0.6, 0.2> } finish { ambient 0.3 } }
#declare Chalk = texture { pigment { rgb <0.9, 0.9, 0.9> } finish { ambient 0.3 phong 0.6 } }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_pattern { png "assets/map-rgb.png" interpolate 2 }
    color_map { [0 rgb <0, 0, 0.3>] [0.5 rgb <1, 0.4, 0>] [1 rgb <1, 1, 0.6>] } }
  finish { ambient 0.5 diffuse 0.5 } scale 1.6 translate <-2.6, -0.8, 0> }
box { <0, 0, 0>, <1, 1, 0.1>
  texture { image_pattern { png "assets/alpha.png" use_alpha }
    texture_map { [0 Leaf] [1 Chalk] } }
  scale 1.6 translate <-0.8, -0.8, 0> }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_pattern { png "assets/palette.png" use_index }
    color_map { [0.3 rgb <1, 0, 0>] [0.6 rgb <0, 0, 1>] } }
  finish { ambient 0.5 diffuse 0.5 } scale 1.6 translate <1, -0.8, 0> }
