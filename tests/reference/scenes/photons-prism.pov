// Refraction photons through a dispersing glass prism: parallel light through a glass bar
// of triangular section is split into the spectrum on the floor beside its shadow
// (dispersion with dispersion_samples), and the camera sees the floor through the prism,
// dispersed too. The light enters through the bar's flat top, which lies on its bounding
// box's face.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 6
  photons { count 40000 gather 15, 60 autostop 0 jitter 0.4 }
}
camera { location <1, 6, -5> look_at <1.2, 0, 0.3> angle 45 }
light_source {
  <-8, 4, 0> color rgb 1.5
  parallel point_at <0, 0, 0>
  photons { refraction on reflection off }
}
plane {
  y, 0
  pigment { color rgb 0.7 }
  finish { ambient 0.05 diffuse 0.8 }
}
prism {
  linear_sweep linear_spline -1, 1, 4,
  <-0.6, -0.5>, <0.6, -0.5>, <0, 0.55>, <-0.6, -0.5>
  rotate <90, 0, 0>
  translate <-0.5, 1.2, 0>
  pigment { rgbf <1, 1, 1, 0.97> }
  finish { ambient 0 diffuse 0 specular 0.4 roughness 0.01 }
  interior { ior 1.5 dispersion 1.2 dispersion_samples 9 }
  photons { target refraction on reflection off collect off }
}
