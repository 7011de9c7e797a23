// height_field from a 16-bit grey PNG (smooth, with a water level) and from a function
// (flat-shaded triangles), lit from the side so the facets show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -4.2> look_at <0, 0.1, 0> angle 50 }
light_source { <-4, 6, -3> rgb 1 }
light_source { <4, 3, -5> rgb 0.4 shadowless }
background { rgb <0.3, 0.4, 0.6> }
height_field { png "assets/terrain.png" smooth water_level 0.3
  pigment { gradient y color_map { [0 rgb <0.2, 0.5, 0.2>] [0.7 rgb <0.6, 0.5, 0.3>] [1 rgb 1] } }
  finish { ambient 0.15 diffuse 0.8 }
  translate <-0.5, 0, -0.5> scale <2, 0.8, 2> translate <-1.1, 0, 0> }
height_field { function 24, 24 { 0.5 + 0.4 * sin(x * 9) * cos(y * 6) }
  pigment { rgb <0.8, 0.6, 0.4> } finish { ambient 0.15 diffuse 0.8 }
  translate <-0.5, 0, -0.5> scale <1.8, 0.6, 1.8> rotate y * 20 translate <1.2, 0, 0.2> }
plane { y, 0.05 pigment { rgb <0.2, 0.3, 0.6> } }
