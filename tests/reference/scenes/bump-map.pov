// bump_map: a grey PNG as a relief on a tilted square (planar, tiled twice), on a sphere
// (spherical, interpolated, larger bumps) and on a cylinder (cylindrical).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -6> look_at <0, 0, 0> angle 50 }
light_source { <-5, 6, -5> rgb 1 }
light_source { <5, 2, -4> rgb 0.3 shadowless }
#declare Plaster = texture { pigment { rgb <0.9, 0.85, 0.8> } finish { ambient 0.1 diffuse 0.8 specular 0.3 roughness 0.02 } }
box { <0, 0, 0>, <2, 2, 0.1>
  texture { Plaster normal { bump_map { png "assets/bumps.png" bump_size 2 } } }
  rotate x * -20 translate <-3.2, -1, 0> }
sphere { 0, 1.1
  texture { Plaster normal { bump_map { png "assets/bumps.png" map_type 1 interpolate 2 bump_size 4 } } }
  rotate y * 30 translate <0, 0.2, 0> }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.8
  texture { Plaster normal { bump_map { png "assets/bumps.png" map_type 2 } } }
  scale <1, 2, 1> translate <2.3, -1, 0> }
