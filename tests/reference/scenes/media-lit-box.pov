// A box of scattering media lit by a point light above it, seen through its front face:
// the samples on the face the viewing rays enter by are lit as those inside are, not
// dimmed by the box's media all the way to the light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -7> look_at <0, 0, 0> angle 50 }
background { rgb 0 }
light_source { <-1, 6, -3> rgb <1, 0.9, 0.7> }
box { <-2.5, -1.5, -1.5>, <2.5, 1.5, 1.5> hollow pigment { rgbt 1 }
  interior { media { scattering { 1, 0.15 } } } }
sphere { <0.5, -0.3, 0>, 0.8 pigment { rgb <0.3, 0.5, 0.8> } }
