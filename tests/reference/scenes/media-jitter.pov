// The spotlight beam of media-beam.pov sampled with full jitter and fewer samples: its
// noise agrees with POV-Ray's only at the level a viewer sees.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 1.5, 0> angle 55 }
light_source { <0, 8, 0> rgb 3 spotlight point_at <0, 0, 0> radius 12 falloff 18 tightness 1 }
light_source { <-10, 10, -10> rgb 0.3 media_interaction off }
plane { y, 0 hollow pigment { rgb 0.7 } }
plane { z, 6 hollow pigment { rgb 0.5 } }
sphere { <0, 3.5, 0>, 0.6 pigment { rgb <0.8, 0.2, 0.2> } }
media { scattering { 1, 0.04 } samples 6, 6 jitter 1 }
