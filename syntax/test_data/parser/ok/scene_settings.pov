// Camera forms, light forms, global settings, atmosphere.
camera { perspective location <0, 1, -5> look_at 0 right x*image_width/image_height up y sky y angle 45 }
camera { fisheye angle 180 }
camera { cylinder 1 location 0 direction z }
camera { panoramic aperture 0.4 blur_samples 20 focal_point <0, 0, 0> confidence 0.9 variance 1/128 }
camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } location <0, 0, 0.01> }
light_source { <0, 10, -10> color rgb 1 }
light_source { <0, 10, 0> color rgb 1 spotlight point_at 0 radius 10 falloff 20 tightness 10 }
light_source { <0, 10, 0> color rgb 1 cylinder point_at 0 }
light_source { <0, 10, 0> color rgb 1 parallel point_at 0 }
light_source { <0, 10, 0>, rgb 1 area_light <4, 0, 0>, <0, 0, 4>, 5, 5 adaptive 1 jitter circular orient }
light_source { 0 White shadowless fade_distance 5 fade_power 2 media_interaction off looks_like { sphere { 0, 0.1 } } }
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  ambient_light rgb 0.2
  charset utf8
  radiosity { pretrace_start 0.08 pretrace_end 0.01 count 150 nearest_count 10 error_bound 0.5 recursion_limit 2 brightness 1 }
  photons { spacing 0.02 autostop 0 jitter 0.4 max_trace_level 5 }
}
background { color rgb <0.1, 0.2, 0.3> }
fog { fog_type 2 distance 10 color rgbf <1, 1, 1, 0.1> fog_offset 0.1 fog_alt 0.2 turbulence 0.2 }
rainbow { angle 42.5 width 5 distance 1e3 direction <-0.2, -0.2, 1> jitter 0.01
  color_map { [0 rgbt <1, 0, 0, 0.9>] [1 rgbt <0, 0, 1, 0.9>] } arc_angle 120 falloff_angle 30 }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0.3, 0.4, 1>] } } emission 0.5 }
media { intervals 1 samples 10, 10 method 3 absorption 0.1 }
