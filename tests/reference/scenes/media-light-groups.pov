// Light groups in a scene with media: each stretch of a ray lights the media along it
// (its container's or the box's around it) with the lights of the object the stretch
// ends at, as POV-Ray does: the green group light shows in the group's own medium and in
// the box's medium in front of and inside the group's objects, the blue one (with the
// scene's lights too) inside the clear ball it groups, the red scene light elsewhere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 40 }
background { rgb 0 }
light_source { <-5, 3, -5> rgb <1, 0.3, 0.2> }
light_group {
  light_source { <5, 3, -5> rgb <0.2, 1, 0.3> }
  sphere { <-1.3, 0.5, 0>, 0.8 hollow pigment { rgbt 1 }
    interior { media { scattering { 1, 0.6 } } } }
  sphere { <1.4, 0.6, 0.5>, 0.6 pigment { rgb 1 } }
}
light_group {
  light_source { <0, -4, -4> rgb <0.3, 0.4, 1> }
  sphere { <0, -1, 0>, 0.8 hollow pigment { rgbt 1 } }
  global_lights on
}
box { <-3, -2, -1.5>, <3, 2, 1.5> hollow pigment { rgbt 1 }
  interior { media { scattering { 1, 0.15 } } } }
