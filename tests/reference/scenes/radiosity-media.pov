// Radiosity with media it leaves out (radiosity's media off, the default): a clear ball
// of glowing media beside a box lights nothing by radiosity, though the camera sees it,
// as the mesh_camera demo room's glowing light bulbs light nothing in POV-Ray.
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { count 60 error_bound 0.5 nearest_count 5 recursion_limit 1 } }
#default { finish { ambient 0 diffuse 1 } }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 50 }
background { rgb 0 }
light_source { <3, 5, -4> rgb 0.8 }
plane { y, 0 pigment { rgb 0.8 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { rgb <0.9, 0.6, 0.3> } }
sphere { <-1.5, 1, 0>, 0.7 hollow no_shadow pigment { rgbt 1 } finish { diffuse 0 }
  interior { media { emission <0.5, 1, 2> } } }
