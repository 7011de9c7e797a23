// Interior fidelity: glass and water spheres (ior, filter and transmit), total internal
// reflection in a glass block, fade_distance and fade_power, and coloured shadows
// through transparent objects.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
background { color rgb <0.6, 0.7, 0.8> }
camera { location <0, 3.5, -9> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 9, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb <0.9, 0.85, 0.8>, rgb <0.25, 0.3, 0.35> } }
plane { z, 6 pigment { gradient x color_map { [0 rgb <1, 0.2, 0.1>] [0.5 rgb <0.1, 0.3, 1>] [1 rgb <1, 0.2, 0.1>] } } }
sphere { <-3.5, 0.3, 0>, 1.3 pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { specular 0.6 roughness 0.01 reflection 0.05 } interior { ior 1.5 } }
sphere { <0, 0.3, 0>, 1.3 pigment { rgbt <0.3, 0.5, 1, 0.7> } interior { ior 1.33 fade_distance 1 fade_power 2 fade_color rgb <0.2, 0.4, 1> } }
box { <-1, -1, -1>, <1, 1, 1> rotate <0, 35, 20> translate <3.5, 0.5, 0>
  pigment { rgbf <1, 0.7, 0.7, 0.95> } interior { ior 2.2 } }
sphere { <1.5, -0.5, -2.5>, 0.5 pigment { rgbt <1, 1, 0.2, 0.6> } }
