// image_map transparency: a palette PNG whose index 1 is transparent in the file (tRNS),
// with index 2 given a filter in the scene and the whole image some transmit; a grey and
// alpha PNG whose alpha fades out; both over a checkered wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 4, -6> rgb 1 }
plane { -z, -1 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.5> scale 0.4 } }
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "assets/palette.png" filter 2, 0.8 transmit all 0.1 } }
  finish { ambient 0.6 diffuse 0.4 } scale 1.8 translate <-2.1, -0.9, 0> }
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "assets/alpha.png" interpolate 2 } }
  finish { ambient 0.6 diffuse 0.4 } scale 1.8 translate <0.3, -0.9, 0> }
