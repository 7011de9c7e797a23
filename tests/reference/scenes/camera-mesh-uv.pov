// mesh_camera, distribution 3: each image position names a point of uv space (u across,
// v up), and the first face whose uv triangle holds it gives the ray, from the point of the
// face with the same barycentric coordinates. The faces lie on a sphere cap around the
// camera point, their corner normals radial, so with `smooth` the rays fan out as a
// pinhole camera's do; antialiasing refines them, as it cannot for the other distributions.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Columns = 16;
#declare Rows = 12;
#macro Lens(U, V)
  #local Direction = vnormalize(<(U - 0.5) * 1.6, (V - 0.5) * 1.2, 1>);
  (<0, 0.4, -4.5> + Direction)
#end
#macro LensNormal(U, V)
  vnormalize(<(U - 0.5) * 1.6, (V - 0.5) * 1.2, 1>)
#end
#declare Lens_Mesh = mesh {
  #declare Row = 0;
  #while (Row < Rows)
    #declare Col = 0;
    #while (Col < Columns)
      #declare U0 = Col / Columns;
      #declare U1 = (Col + 1) / Columns;
      #declare V0 = Row / Rows;
      #declare V1 = (Row + 1) / Rows;
      // Corners a, b, c ordered so that (c - a) x (b - a) points away from the camera point.
      smooth_triangle {
        Lens(U0, V0), LensNormal(U0, V0), Lens(U1, V1), LensNormal(U1, V1), Lens(U1, V0), LensNormal(U1, V0)
        uv_vectors <U0, V0>, <U1, V1>, <U1, V0>
      }
      smooth_triangle {
        Lens(U0, V0), LensNormal(U0, V0), Lens(U0, V1), LensNormal(U0, V1), Lens(U1, V1), LensNormal(U1, V1)
        uv_vectors <U0, V0>, <U0, V1>, <U1, V1>
      }
      #declare Col = Col + 1;
    #end
    #declare Row = Row + 1;
  #end
}
camera { mesh_camera { 1 3 mesh { Lens_Mesh rotate x * 8 } smooth } }
light_source { <-4, 6, -8> rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.9, 0.8>, rgb <0.2, 0.3, 0.5> } }
sphere { <-0.7, 0, 1>, 0.9 pigment { rgb <0.9, 0.3, 0.1> } finish { specular 0.4 } }
box { <0.4, -1, 0>, <1.6, 0.4, 1.2> rotate y * 30 pigment { rgb <0.2, 0.7, 0.3> } }
