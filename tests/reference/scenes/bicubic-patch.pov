// bicubic_patch: types 0 and 1, u_steps and v_steps alike and unlike, flatness, and a
// uv-mapped checker over uv_vectors.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 9, -10> look_at <0, 0.3, -1> angle 55 }
light_source { <-5, 10, -6> rgb 1 }

#macro Points()
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
#end
bicubic_patch { type 0 u_steps 3 v_steps 3 Points()
  pigment { rgb <1, 0.7, 0.3> } finish { phong 0.6 }
  rotate -90*x translate <-4.6, 0.8, -1.5> }
bicubic_patch { type 1 flatness 0.05 u_steps 4 v_steps 2 Points()
  pigment { rgb <0.4, 0.8, 1> } finish { specular 0.6 }
  rotate -90*x rotate 20*y translate <-1.2, 0.8, -0.5> }
bicubic_patch { type 1 u_steps 3 v_steps 3 uv_vectors <0, 0>, <2, 0>, <2, 1>, <0, 1>
  <0, 0, 0>, <1, 0, 1>, <2, 0, 1>, <3, 0, 0>,
  <0, 1, 1>, <1, 1, 2>, <2, 1, 2>, <3, 1, 1>,
  <0, 2, 1>, <1, 2, 2>, <2, 2, 2>, <3, 2, 1>,
  <0, 3, 0>, <1, 3, 1>, <2, 3, 1>, <3, 3, 0>
  texture { uv_mapping pigment { checker rgb <0.2, 0.3, 0.9> rgb 1 scale 0.25 } }
  rotate -90*x translate <1.6, 0, -2> }
plane { y, 0 pigment { rgb 0.75 } }
