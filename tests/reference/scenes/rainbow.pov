// Rainbows of their own: a bow at 42 degrees around the anti-solar direction and a wider
// one outside it, each an arc narrower than the full circle fading towards its ends, mixed
// in as fog is by distance (nearer objects show less of it), over hills and a tower.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 6, 0> angle 90 }
light_source { <-20, 30, -60> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.55, 0.6, 0.7>] [0.5 rgb <0.2, 0.25, 0.45>] } } }
plane { y, 0 pigment { rgb <0.25, 0.45, 0.2> } }
sphere { <-25, -12, 60>, 22 pigment { rgb <0.3, 0.45, 0.25> } }
sphere { <30, -20, 80>, 32 pigment { rgb <0.35, 0.4, 0.25> } }
box { <3, 0, 4>, <5, 9, 6> pigment { rgb <0.7, 0.65, 0.55> } }
#declare Spectrum = color_map {
  [0.00 rgbt <1, 1, 1, 1>]
  [0.10 rgbt <0.5, 0, 1, 0.6>]
  [0.30 rgbt <0, 0, 1, 0.4>]
  [0.50 rgbt <0, 1, 0, 0.4>]
  [0.70 rgbt <1, 1, 0, 0.4>]
  [0.90 rgbt <1, 0, 0, 0.5>]
  [1.00 rgbt <1, 1, 1, 1>]
}
rainbow {
  direction <0.1, -0.45, 1> up y
  angle 42 width 5 distance 60
  color_map { Spectrum }
  arc_angle 150 falloff_angle 90
}
rainbow {
  direction <0.1, -0.45, 1> up y
  angle 51 width 6 distance 60
  color_map { Spectrum }
  arc_angle 120 falloff_angle 40
}
