// Object statements and modifiers.
sphere { <0, 1, 0>, 1 hollow double_illuminate no_shadow no_reflection no_image }
box { <-1, -1, -1>, <1, 1, 1> rotate <0, 45, 0> }
cylinder { 0, y, 0.5 open }
cone { 0, 1, y, 0 }
plane { y, -1 }
torus { 1, 0.25 sturm }
disc { 0, y, 2, 1 }
blob { threshold 0.6 sphere { 0, 1, 1 } cylinder { 0, x, 0.5, 1 } }
lathe { quadratic_spline 4, <0, 0>, <1, 0>, <1, 1>, <0, 2> }
prism { linear_sweep linear_spline 0, 1, 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
sor { 4, <0, 0>, <1, 0>, <1, 1>, <0, 2> }
sphere_sweep { linear_spline 2, <0, 0, 0>, 0.1, <1, 0, 0>, 0.2 tolerance 0.01 }
superellipsoid { <0.25, 0.25> }
text { ttf "timrom.ttf" "POV" 0.2, 0 }
height_field { png "mount.png" smooth water_level 0.1 }
isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } max_gradient 4 }
parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }
julia_fractal { <-0.08, 0.7, 0, 0> quaternion sqr max_iteration 8 precision 15 }
polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
smooth_triangle { <0, 0, 0>, y, <1, 0, 0>, y, <0, 1, 0>, y }
mesh { triangle { 0, x, y } inside_vector z }
mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  face_indices { 1, <0, 1, 2> }
}
bicubic_patch { type 1 flatness 0.1 u_steps 4 v_steps 4
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>
  <0, 3, 0>, <1, 3, 0>, <2, 3, 0>, <3, 3, 0>
}
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, -1> }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
intersection { sphere { 0, 1 } plane { y, 0 } bounded_by { box { -1, 1 } } clipped_by { plane { x, 0 } } }
difference { box { -1, 1 } cylinder { -2*z, 2*z, 0.5 } cutaway_textures }
merge { sphere { 0, 1 } sphere { x, 1 } split_union off }
object { O scale 2 translate <1, 0, 0> matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> }
light_group { light_source { 0, 1 } sphere { 0, 1 } global_lights off }
