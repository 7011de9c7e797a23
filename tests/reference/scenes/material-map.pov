// material_map: a palette image's indices choosing among three textures (index 3 takes the
// last), an RGB image's red values (interpolated) counting round five textures, a
// palette image wrapped round a sphere (map_type 1) and turned, and a `once` map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 4, -6> rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
#declare Red = texture { pigment { rgb <0.9, 0.1, 0.1> } finish { ambient 0.3 } }
#declare Green = texture { pigment { rgb <0.1, 0.8, 0.2> } finish { ambient 0.3 phong 0.5 } }
#declare Blue = texture { pigment { rgb <0.1, 0.2, 0.9> } finish { ambient 0.3 } }
#declare White = texture { pigment { rgb 0.9 } finish { ambient 0.4 diffuse 0.5 } }
#declare Black = texture { pigment { rgb 0.05 } finish { ambient 0.3 specular 0.6 } }
box { <0, 0, 0>, <1, 1, 0.1>
  texture { material_map { png "assets/palette.png" texture { Red } texture { Green } texture { Blue } } }
  scale 1.6 translate <-2.6, -1.6, 0> }
box { <0, 0, 0>, <1, 1, 0.1>
  texture { material_map { png "assets/map-rgb.png" interpolate 2
    texture { Red } texture { Green } texture { Blue } texture { White } texture { Black } } }
  scale 1.6 translate <-0.8, -1.6, 0> }
sphere { 0, 1
  texture { material_map { png "assets/palette.png" map_type 1
    texture { White } texture { Blue } texture { Black } texture { Green } }
    rotate y * 30 }
  translate <1.8, -0.2, 0> }
box { <0, 0, 0>, <1, 1, 0.1>
  texture { material_map { png "assets/map-rgb.png" once
    texture { Blue } texture { White } texture { Red } } }
  scale <3, 0.8, 1> translate <-2.6, 0.4, 0> }
