// Meshes: flat and smooth triangles, a texture per triangle and textures blended across
// one (texture_list), copies of one mesh (object { M }), and a closed mesh with an
// inside_vector cut by CSG.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <6, 6, -4> rgb 0.4 shadowless }

#declare Red = texture { pigment { rgb <1, 0.25, 0.2> } finish { phong 0.4 } }
#declare Green = texture { pigment { rgb <0.3, 0.9, 0.3> } }
#declare Blue = texture { pigment { rgb <0.2, 0.35, 1> } finish { specular 0.5 } }

// A tent of two smooth triangles and a flat one, each with its own texture.
#declare Tent = mesh {
  smooth_triangle { <-1, 0, 0>, <-1, 1, -0.3>, <0, 1.5, 0>, <0, 1, -0.5>, <0, 0, -1>, <-0.5, 0.5, -1>
    texture_list { Red Green Blue } }
  smooth_triangle { <1, 0, 0>, <1, 1, -0.3>, <0, 1.5, 0>, <0, 1, -0.5>, <0, 0, -1>, <0.5, 0.5, -1>
    texture_list { Blue Green Red } }
  triangle { <-1, 0, 0>, <1, 0, 0>, <0, 1.5, 0> texture { Green } }
  texture { pigment { rgb 1 } }
}
object { Tent translate <-2.5, 0, 0> }
object { Tent rotate 150*y translate <-0.2, 0, 1.5> }

// A closed octahedron with an inside, hollowed by a sphere.
#declare Octahedron = mesh {
  #declare P = array[6] { x, -x, y, -y, z, -z }
  #for (I, 0, 1)
    #for (J, 2, 3)
      #for (K, 4, 5)
        triangle { P[I], P[J], P[K] }
      #end
    #end
  #end
  inside_vector <0.1, 0.2, 1>
}
difference {
  object { Octahedron scale 1.4 }
  sphere { <0, 0, -0.6>, 0.9 }
  pigment { rgb <1, 0.8, 0.3> }
  finish { phong 0.6 }
  translate <2.6, 1.4, 0>
}
plane { y, 0 pigment { checker rgb 0.5 rgb 0.8 } }
