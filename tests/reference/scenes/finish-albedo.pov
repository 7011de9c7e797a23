// Finish amounts given as albedos: diffuse albedo with brilliances 0.5, 1 and 4 (top
// row), phong albedo and specular albedo at two sizes each (bottom row), and a thin
// disc lit from behind with diffuse albedo's backside amount.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.2, 0.25, 0.3> }
camera { location <0, 0.5, -11> look_at <0, 0.3, 0> angle 45 }
light_source { <-6, 10, -12> color rgb 1 }
light_source { <4, 2, 8> color rgb 0.7 }
#declare P = pigment { rgb <0.9, 0.7, 0.5> }
sphere { <-3, 1.6, 0>, 0.9 pigment { P } finish { diffuse albedo 0.5 brilliance 0.5 } }
sphere { <-1, 1.6, 0>, 0.9 pigment { P } finish { diffuse albedo 0.5 } }
sphere { < 1, 1.6, 0>, 0.9 pigment { P } finish { brilliance 4 diffuse albedo 0.5 } }
disc { <3, 1.6, 0.5>, <0.3, 0, -1>, 0.9
  pigment { rgb <0.5, 0.9, 0.6> } finish { diffuse albedo 0.3, 0.4 brilliance 2 } }
sphere { <-3, -0.6, 0>, 0.9 pigment { P } finish { phong albedo 0.4 phong_size 5 } }
sphere { <-1, -0.6, 0>, 0.9 pigment { P } finish { phong albedo 0.2 phong_size 60 } }
sphere { < 1, -0.6, 0>, 0.9 pigment { P } finish { specular albedo 0.4 roughness 0.2 } }
sphere { < 3, -0.6, 0>, 0.9 pigment { P } finish { specular albedo 0.2 roughness 0.01 } }
plane { y, -1.6 pigment { rgb 0.6 } }
