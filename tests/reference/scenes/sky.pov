// A layered sky sphere with emission, a rainbow arc against it and a mirror ball.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 2, 0> angle 70 }
light_source { <10, 20, -20> rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.7, 0.8, 1>] [1 rgb <0.1, 0.2, 0.6>] } }
  pigment { gradient x color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 0.9, 0.8, 0.4>] [1 rgbt <1, 1, 1, 1>] } scale 2 translate -x }
  emission rgb <1, 0.95, 0.9>
  rotate 10*z
}
rainbow {
  direction <0, -0.1, 1> angle 30 width 6 distance 1e6
  color_map { [0 rgbt <1, 0, 0, 0.4>] [0.3 rgbt <1, 1, 0, 0.5>] [0.6 rgbt <0, 1, 0, 0.6>] [1 rgbt <0, 0, 1, 1>] }
  arc_angle 140 falloff_angle 60
}
plane { y, 0 pigment { rgb <0.3, 0.5, 0.2> } }
sphere { <1.5, 1, 1>, 1 pigment { rgb 0.1 } finish { reflection 0.8 specular 0.5 } }
