// Atmospheric media seen against the background: POV-Ray samples a ray that meets
// nothing out to 2e10 units, so the haze dims the blue background to black and a
// spotlight's beam shows against it beyond the floor's edge.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 1.5, 0> angle 60 }
background { rgb <0.2, 0.3, 0.6> }
light_source { <-4, 6, 2> rgb 2 spotlight point_at <3, 0, 4> radius 8 falloff 12 }
light_source { <0, 10, -10> rgb 0.4 media_interaction off }
box { <-3, -0.1, -3>, <3, 0, 3> pigment { rgb 0.7 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } }
media { scattering { 1, 0.05 } absorption 0.01 }
