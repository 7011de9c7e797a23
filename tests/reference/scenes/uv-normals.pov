// Normals under uv_mapping on mesh2 quads with uv_vectors: the pattern is evaluated at
// (u, v, 0) and stays glued to the surface when the object turns, while its push turns
// with the object (textures given before the rotations). Patterns without noise, so
// that the pictures match pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at 0 right x*4 up y*3 }
background { rgb 0.1 }
light_source { <-3, 5, -6> rgb 1 }
#declare Quad = mesh2 {
  vertex_vectors { 4, <-0.7, -0.6, 0>, <0.7, -0.6, 0>, <0.7, 0.6, 0>, <-0.7, 0.6, 0> }
  uv_vectors { 4, <1.5, 1.5>, <2.5, 1.5>, <2.5, 2.5>, <1.5, 2.5> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
}
#declare Lit = finish { specular 0.4 }
object { Quad
  texture { uv_mapping pigment { rgb 0.8 } normal { gradient x 0.5 scale 0.3 } finish { Lit } }
  rotate z*90 rotate y*20 translate <-1, 0.75, 0> }
object { Quad
  texture { uv_mapping pigment { rgb <0.9, 0.8, 0.6> } normal { quilted 0.6 scale 0.12 } finish { Lit } }
  rotate -30*z translate <1, 0.75, 0> }
object { Quad
  texture { uv_mapping pigment { rgb <0.6, 0.8, 0.9> }
    normal { gradient y normal_map { [0.5 gradient x 0.8 scale 0.1] [0.5 gradient y -0.8 scale 0.1] } }
    finish { Lit } }
  rotate x*-40 translate <-1, -0.75, 0> }
object { Quad
  texture { uv_mapping pigment { rgb 0.8 } normal { onion 0.5 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.4 } finish { Lit } }
  rotate y*-35 translate <1, -0.75, 0> }
