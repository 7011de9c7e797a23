// Media photons: a spotlight shines through a glass lens into a box of scattering medium.
// The lens refracts the light's photons, so the direct light behind it is left to them:
// they are left in the medium on their way (photons { media }) and draw the converging
// cone of the focused beam; the light that passes beside the lens reaches the medium
// directly and is scattered as usual.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 5
  photons { count 20000 media 60, 1 jitter 0.4 autostop 0 }
}
camera { location <0.5, 7, -5> look_at <0.5, 0.3, 0> angle 38 }
light_source {
  <-12, 0.8, 0> color rgb 1.5
  spotlight radius 3 falloff 4 point_at <0, 0.8, 0>
  photons { refraction on reflection off }
}
light_source { <2, 20, -10> color rgb 0.25 media_interaction off photons { refraction off reflection off } }
plane { y, 0 pigment { checker color rgb 0.55 color rgb 0.25 } finish { diffuse 0.8 } }
sphere {
  <-2.6, 0.8, 0>, 0.55
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.01 }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
box {
  <-2, 0.01, -1.6>, <3.5, 1.8, 1.6>
  hollow
  pigment { rgbf 1 }
  interior { media { scattering { 1, rgb 0.35 extinction 0 } method 3 intervals 1 samples 6 } }
  photons { collect on }
}
