// Refraction photons through absorbing media: a glass ball whose interior holds an
// absorbing medium (more in blue and green than red) focuses a point light into a caustic
// on the floor, tinted and dimmed by the medium the photons cross.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { count 30000 gather 15, 60 autostop 0 jitter 0.4 }
}
camera { location <0, 4, -5> look_at <0, 0.4, 0.5> angle 45 }
light_source {
  <-2, 6, 2> color rgb 1.3
  photons { refraction on reflection off }
}
plane {
  y, 0
  pigment { color rgb 0.8 }
  finish { ambient 0.05 diffuse 0.8 }
}
sphere {
  <0, 1.1, 0.5>, 0.8
  hollow
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 specular 0.5 roughness 0.01 }
  interior { ior 1.45 media { absorption <0.2, 0.9, 1.6> } }
  photons { target refraction on reflection off collect off }
}
