#declare Red = texture { pigment { rgb x } }
#declare M = mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0, 0>, <1, 0>, <0, 1> texture { Red } }
  smooth_triangle { 0, -z, x, -z, y, -z texture_list { Red Red Red } }
  inside_vector z
  hierarchy off
}
object { M uv_mapping pigment { uv_mapping checker } }
mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  normal_vectors { 1, -z }
  uv_vectors { 3, <0, 0>, <1, 0>, <0, 1> }
  texture_list { 2, texture { Red }, texture { uv_mapping pigment { checker } } }
  face_indices { 1, <0, 1, 2>, 0, 1, 1 }
  normal_indices { 1, <0, 0, 0> }
  uv_indices { 1, <0, 1, 2> }
}
polygon { 5, <0, 0>, <1, 0> <1, 1> <0, 1>, <0, 0> }
bicubic_patch { type 1 flatness 0.01 u_steps 3 v_steps 3
  uv_vectors <0, 0>, <1, 0>, <1, 1>, <0, 1>
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
}
light_group { light_source { <0, 10, 0> rgb 1 } sphere { 0, 1 } global_lights on }
