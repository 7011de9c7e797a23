// mesh_camera, distribution 0: one face per pixel, numbered row by row from the top left,
// each ray from its face's centroid along the face's normal. Two meshes, the second 3/8 of a
// pixel to the right, give each pixel two rays, averaged. The faces face +z: POV-Ray's
// mesh camera points a face's normal along (c - a) x (b - a).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare W = 96;
#declare H = 72;
#declare Faces = mesh {
  #declare Row = 0;
  #while (Row < H)
    #declare Col = 0;
    #while (Col < W)
      #declare X = (Col + 0.5) / W * 4 - 2;
      #declare Y = 1.5 - (Row + 0.5) / H * 3;
      triangle { <X - 0.01, Y - 0.01, -6>, <X - 0.01, Y + 0.02, -6>, <X + 0.02, Y - 0.01, -6> }
      #declare Col = Col + 1;
    #end
    #declare Row = Row + 1;
  #end
}
camera {
  mesh_camera { 2 0 mesh { Faces rotate x * 12 } mesh { Faces translate <1.5 / W, 0, 0> rotate x * 12 } }
  location <0, 0, 0.5>
}
light_source { <-4, 6, -8> rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.9, 0.8>, rgb <0.2, 0.3, 0.5> } }
sphere { <-0.7, 0, 1>, 0.9 pigment { rgb <0.9, 0.3, 0.1> } finish { specular 0.4 } }
box { <0.4, -1, 0>, <1.6, 0.4, 1.2> rotate y * 30 pigment { rgb <0.2, 0.7, 0.3> } }
