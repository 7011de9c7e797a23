// Noise statistics: bozo mapped to grey on a plane facing the camera, lit by ambient light
// only. Noise need not match POV-Ray point for point; tests/tests/fidelity.rs compares the
// distribution and spatial frequency of the values instead.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8*x up 6*y }
light_source { <0, 0, -100> color rgb 1 }
plane { z, 0 pigment { bozo scale 0.25 color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
