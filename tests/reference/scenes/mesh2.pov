// mesh2: a wavy sheet generated in loops with normals and uv vectors per vertex and a
// uv-mapped checker; a second sheet with per-vertex textures (three texture indices per
// face) from a texture_list, one face with a single texture index, normal_indices for the
// leading faces only, and uv_indices.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -8> look_at <0, 0.5, 0> angle 45 }
light_source { <-5, 10, -6> rgb 1 }

#declare N = 12;
#macro Height(X, Z) 0.3 * sin(2 * X) * cos(1.5 * Z) #end
mesh2 {
  vertex_vectors { (N + 1) * (N + 1),
    #for (J, 0, N) #for (I, 0, N)
      #local X = -2 + 4 * I / N; #local Z = -2 + 4 * J / N;
      <X, Height(X, Z), Z>,
    #end #end
  }
  normal_vectors { (N + 1) * (N + 1),
    #for (J, 0, N) #for (I, 0, N)
      #local X = -2 + 4 * I / N; #local Z = -2 + 4 * J / N;
      <-0.6 * cos(2 * X) * cos(1.5 * Z), 1, 0.45 * sin(2 * X) * sin(1.5 * Z)>,
    #end #end
  }
  uv_vectors { (N + 1) * (N + 1),
    #for (J, 0, N) #for (I, 0, N) <I / N, J / N>, #end #end
  }
  face_indices { 2 * N * N,
    #for (J, 0, N - 1) #for (I, 0, N - 1)
      #local A = J * (N + 1) + I;
      <A, A + 1, A + N + 2>, <A, A + N + 2, A + N + 1>,
    #end #end
  }
  texture {
    uv_mapping pigment { checker rgb <0.9, 0.2, 0.1> rgb <1, 0.9, 0.6> scale 1 / 6 }
    finish { phong 0.5 }
  }
  translate <-1.8, 0.5, 0.5>
}

mesh2 {
  vertex_vectors { 6, <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <0, 0, 1>, <1, 0.4, 1>, <2, 0, 1> }
  normal_vectors { 2, <0, 1, 0>, <-0.3, 1, -0.3> }
  uv_vectors { 3, <0, 0>, <1, 0>, <0.5, 1> }
  texture_list { 4,
    texture { pigment { rgb <1, 0, 0> } }
    texture { pigment { rgb <0, 1, 0> } }
    texture { pigment { rgb <0, 0, 1> } }
    texture { uv_mapping pigment { gradient x color_map { [0 rgb 1] [1 rgb 0] } } }
  }
  face_indices { 4,
    <0, 1, 4>, 0, 1, 2,
    <0, 4, 3>, 2, 1, 0,
    <1, 2, 5>, 3,
    <1, 5, 4>, 1, 1, 2
  }
  normal_indices { 2, <0, 0, 1>, <0, 1, 0> }
  uv_indices { 4, <0, 1, 2>, <0, 1, 2>, <0, 1, 2>, <2, 1, 0> }
  scale 1.5 translate <0.8, 0.3, -2.2>
}
plane { y, 0 pigment { rgb 0.7 } }
