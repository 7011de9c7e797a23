// Pattern fidelity: tiling 26, Penrose's kites and darts, on a plane seen from above at a
// slant: the five-fold star round the origin in front, tiles some 60 units away towards
// the top, with a colour map that shows both tile types' bands and their bevels.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.8> }
camera { location <0, 7, -6> look_at <0, 0, 1.5> angle 60 }
light_source { <-5, 30, -10> color rgb 1 }
plane { y, 0
  pigment { tiling 26
    color_map { [0 rgb <0.9, 0.2, 0.1>] [0.3 rgb <0.95, 0.95, 0.3>] [0.5 rgb <0.1, 0.6, 0.3>]
                [0.75 rgb <0.2, 0.8, 0.9>] [1 rgb <0.1, 0.3, 0.9>] }
    scale 0.9 rotate y*8 translate <0.3, 0, 0.2> }
  finish { ambient 0.3 diffuse 0.7 }
}
