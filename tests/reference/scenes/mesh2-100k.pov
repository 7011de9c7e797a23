// A mesh2 of 100,352 triangles generated in loops: a rippled torus with a normal and a uv
// vector per vertex and a uv-mapped checker, for the hierarchy over mesh triangles.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 7, -9> look_at <0, 0, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
#declare U = 448;
#declare V = 112;
#declare Major = 3;
#macro Minor(A, B) (0.9 + 0.08 * sin(12 * A) * sin(6 * B)) #end
#macro Point(I, J)
  #local A = 2 * pi * I / U; #local B = 2 * pi * J / V;
  #local R = Minor(A, B);
  <(Major + R * cos(B)) * cos(A), R * sin(B), (Major + R * cos(B)) * sin(A)>
#end
mesh2 {
  vertex_vectors { U * V,
    #for (J, 0, V - 1) #for (I, 0, U - 1) Point(I, J), #end #end
  }
  uv_vectors { U * V,
    #for (J, 0, V - 1) #for (I, 0, U - 1) <I / U, J / V>, #end #end
  }
  face_indices { 2 * U * V,
    #for (J, 0, V - 1) #for (I, 0, U - 1)
      #local A = J * U + I;
      #local B = J * U + mod(I + 1, U);
      #local C = mod(J + 1, V) * U + mod(I + 1, U);
      #local D = mod(J + 1, V) * U + I;
      <A, B, C>, <A, C, D>,
    #end #end
  }
  texture {
    uv_mapping pigment { checker rgb <0.9, 0.3, 0.1> rgb <1, 0.95, 0.8> scale <1 / 32, 1 / 8, 1> }
    finish { phong 0.4 }
  }
}
plane { y, -1.2 pigment { rgb 0.6 } }
