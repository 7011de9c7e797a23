// Reflection photons: a mirrored half ring on a matte floor throws the cardioid caustic of
// a point light onto it.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { spacing 0.02 gather 20, 100 }
}
camera { location <0, 8, -5> look_at <0, 0, 0> angle 40 }
light_source {
  <-6, 3, -0.5> color rgb 1.2
  photons { reflection on refraction off }
}
plane {
  y, 0
  pigment { color rgb <0.6, 0.6, 0.55> }
  finish { ambient 0.05 diffuse 0.8 }
}
difference {
  cylinder { <0, 0, 0>, <0, 0.6, 0>, 1.3 }
  cylinder { <0, -0.1, 0>, <0, 0.7, 0>, 1.22 }
  box { <0, -1, -3>, <-3, 2, 3> }
  pigment { color rgb <0.9, 0.85, 0.7> }
  finish { ambient 0 diffuse 0.1 reflection 0.9 }
  photons { target reflection on refraction off collect off }
}
