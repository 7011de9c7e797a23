// The entries of a pattern's map are evaluated in the pattern's space: transformations
// written before the map move them too, and a slope's altitude inside a texture_map
// follows the outer pattern's scale. Four columns: pigment_map, texture_map with slope
// altitude, normal_map, and the same pigment_map with the scale after the map.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 1.5, -10> look_at <0, 1.5, 0> right x * 8 up y * 6 }
light_source { <-3, 5, -10> rgb 1 }

#declare Stripes = pigment { gradient y color_map { [0 rgb <0, 0, 0.3>] [1 rgb <1, 0.9, 0.6>] } }
#declare Bands = texture {
  pigment { slope { x, 0, 1 altitude y, 0, 1 } color_map { [0 rgb 0] [1 rgb <0.4, 1, 0.4>] } }
  finish { ambient 1 diffuse 0 }
}
#declare Ridges = normal { gradient y 0.8 }

box { <-3.9, -1.4, 0>, <-2.1, 4.4, 1>
  pigment { gradient y rotate z * 10 scale 6 pigment_map { [0 Stripes] [1 Stripes] } }
  finish { ambient 1 diffuse 0 } }
box { <-1.9, -1.4, 0>, <-0.1, 4.4, 1>
  texture { gradient y scale 8 texture_map { [0 Bands] [1 Bands] } } }
box { <0.1, -1.4, 0>, <1.9, 4.4, 1>
  pigment { rgb 0.8 }
  normal { gradient y scale 5 normal_map { [0 Ridges] [1 Ridges] } }
  finish { ambient 0.1 diffuse 0.9 } }
box { <2.1, -1.4, 0>, <3.9, 4.4, 1>
  pigment { gradient y pigment_map { [0 Stripes] [1 Stripes] } rotate z * 10 scale 6 }
  finish { ambient 1 diffuse 0 } }
