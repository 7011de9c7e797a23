// Emission media glowing in a sphere (a spherical density), absorption media in a box
// with a density map over a gradient, in front of a checkered wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 60 }
light_source { <-5, 10, -10> rgb 1 }
plane { z, 3 hollow pigment { checker rgb 0.9 rgb <0.2, 0.2, 0.4> } }
sphere { <-1.4, 0, 0>, 1.2 hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission <1, 0.6, 0.2> density { spherical color_map { [0 rgb 0] [1 rgb 1.5] } scale 1.2 translate -1.4*x } } }
}
box { <0.3, -1.2, -1>, <2.6, 1.2, 1> hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { absorption <0.3, 0.8, 1.2>
    density { gradient y density_map { [0 rgb 0] [0.5 rgb 0.5] [1 rgb 1.5] } scale 2.4 translate -1.2*y } } }
}
