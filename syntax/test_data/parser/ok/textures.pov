// Textures, patterns, maps, warps and layered textures.
sphere { 0, 1
  texture {
    pigment {
      gradient y
      color_map { [0.0 color Red] [0.5 color rgb <0, 1, 0>] [1.0 color Blue] }
      turbulence 0.5 octaves 4 lambda 2 omega 0.5
      warp { turbulence <0.5, 0.2, 0.1> }
      warp { repeat x flip y }
      warp { black_hole <0, 0, 0>, 1 falloff 2 strength 1 }
      scale 0.5
    }
    normal { ripples 0.5 frequency 3 phase clock }
    finish { ambient 0.1 diffuse 0.7 specular 0.4 roughness 0.01 reflection { 0.1, 0.6 fresnel on metallic } conserve_energy }
  }
  texture { pigment { rgbf <1, 1, 1, 0.8> } }
  interior { ior 1.33 dispersion 1.02 fade_distance 2 fade_power 1001 media { absorption rgb 0.1 } }
}
plane { y, 0
  texture {
    checker
    texture { pigment { White } }
    texture { pigment { Black } }
  }
}
box { -1, 1
  pigment {
    brick color Gray, color Red brick_size <1, 0.5, 0.5> mortar 0.1
  }
  normal { bump_map { png "bumps.png" bump_size 2 interpolate 2 } }
}
sphere { 0, 1
  texture {
    pigment_pattern { agate }
    texture_map { [0.3 T1] [0.7 T2] }
  }
  pigment { image_map { png "tex.png" map_type 1 once filter all 0.5 } }
  normal { average normal_map { [1 bumps 0.5] [1 dents 0.5] } }
  material { texture { uv_mapping pigment { checker } } }
}
sphere { 0, 1 pigment { function { sin(x*10) } color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { 0, 1 pigment { object { box { 0, 1 } } color Red color Blue } }
sphere { 0, 1 normal { slope y slope_map { [0 <0, 1>] [1 <1, 0>] } } }
