// Pattern fidelity: tiling patterns beyond a colour map: a texture map, a pigment map,
// normals with their slopes from the pattern, frequency, phase and a wave type, and a
// tiling wrapped round a sphere. No noise, so that the pictures match pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { location <0, 5, -9> look_at <0, 0, 0.5> angle 50 }
light_source { <-4, 10, -6> color rgb 1 }
plane { y, 0
  texture { tiling 7
    texture_map {
      [0.5 pigment { rgb <0.2, 0.3, 0.8> } finish { phong 0.6 }]
      [0.5 pigment { rgb <0.9, 0.85, 0.7> } normal { tiling 1 0.4 scale 0.1 }]
      [1 pigment { rgb 0.2 }]
    }
    scale 0.6 }
}
box { <-3.5, 0, -1>, <-1.5, 1.5, 1>
  pigment { tiling 5 pigment_map {
    [0 checker rgb 1, rgb <0.8, 0.1, 0.1> scale 0.1] [0.34 rgb <0.1, 0.6, 0.2>] [0.67 rgb <0.9, 0.8, 0.1>] [1 rgb 0] }
    scale 0.5 }
}
sphere { <0, 1, 0>, 1
  pigment { tiling 3 color_map { [0 rgb <0.9, 0.3, 0.1>] [1 rgb <0.1, 0.2, 0.6>] } frequency 2 sine_wave scale 0.3 }
}
box { <1.5, 0, -1>, <3.5, 1.5, 1>
  pigment { rgb 0.8 }
  normal { tiling 9 1.5 scale 0.4 }
}
box { <-1, 0, -3>, <1, 0.4, -2>
  pigment { tiling 24 color_map { [0 rgb 1] [0.5 rgb <0.2, 0.5, 0.9>] [1 rgb 0] } phase 0.2 scale 0.3 rotate y*30 }
}
