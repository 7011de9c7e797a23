// image_map with the four documented map types: planar (tiled and once, interpolated),
// spherical, cylindrical and torus, lit only by ambient light so the image's colours show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -7> look_at <0, 0, 0> angle 60 }
background { rgb <0.2, 0.2, 0.25> }
#declare Flat = finish { ambient 1 diffuse 0 }
// Planar, tiled twice across the box face.
box { <-3.6, 0.4, -0.1>, <-1.2, 2.4, 0.1>
  pigment { image_map { png "assets/map-rgb.png" } scale 1.2 translate <-3.6, 0.4, 0> }
  finish { Flat } }
// Planar, once, bilinear, on a square larger than the image.
box { <-0.9, 0.2, -0.1>, <1.3, 2.4, 0.1>
  pigment { image_map { png "assets/map-rgb.png" once interpolate 2 } scale 1.6 translate <-0.6, 0.5, 0> }
  finish { Flat } }
sphere { 0, 1
  pigment { image_map { png "assets/map-rgb.png" map_type 1 } }
  finish { Flat } rotate <30, 40, 0> translate <2.6, 1.3, 0> }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.9
  pigment { image_map { png "assets/map-rgb.png" map_type 2 } }
  finish { Flat } rotate <20, 30, 0> translate <-2.4, -2.2, 0> }
torus { 1, 0.45
  pigment { image_map { png "assets/map-rgb.png" map_type 5 interpolate 2 } }
  finish { Flat } rotate <-60, 20, 0> translate <1.4, -1.5, 0> }
