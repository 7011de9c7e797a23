// A light group darkens its ball with a negative shadowless light (as abyss.pov's mines
// are darkened) inside a hollow sphere of haze lit from above. Shadowless lights leave
// media dark in POV-Ray 3.7, so the haze in front of the ball stays as bright as
// elsewhere; the negative light darkens the ball's surface below zero, which the haze
// in front of it then brightens. The haze has no extinction: this scene is about the
// lights, not about how media dim the light that crosses them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -8> look_at 0 angle 50 }
background { rgb 0 }
light_source { <-1, 30, -1> rgb <0.1, 0.6, 0.9> * 4 }
light_group {
  sphere { <-1.2, 0, 0>, 1 pigment { rgb 0.3 } finish { ambient 0 diffuse 0.6 } }
  light_source { <-2, -2, -6> rgb -2 shadowless }
  global_lights on
}
sphere { <1.5, 0.3, 1>, 0.8 pigment { rgb 0.3 } finish { ambient 0 diffuse 0.6 } }
sphere { 0, 20 hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, 0.02 extinction 0 } } } }
