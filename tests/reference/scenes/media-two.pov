// Two media in one box, sampled together: a glowing scattering medium without extinction
// and an absorbing one with a density gradient. What the first adds is dimmed by the
// second on its way to the eye, as one medium with both would dim it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -7> look_at <0, 0, 0> angle 50 }
background { rgb 0 }
light_source { <-1, 6, -3> rgb <1, 0.9, 0.7> }
box { <-2.5, -1.5, -1.5>, <2.5, 1.5, 1.5> hollow pigment { rgbt 1 }
  interior {
    media { scattering { 1, 0.2 extinction 0 } emission <0.02, 0.05, 0.1> }
    media { absorption <0.3, 0.2, 0.1> density { gradient x color_map { [0 rgb 0.2] [1 rgb 1] } scale 5 translate -2.5*x } }
  } }
sphere { <0.5, -0.3, 0>, 0.8 pigment { rgb <0.8, 0.5, 0.3> } }
