// Pattern fidelity: tiling 25, Penrose's pentagons, stars, boats and diamonds, on a plane
// seen from above at a slant: the type 0 pentagon round the origin in front, tiles some
// 60 units away towards the top, with a colour map that gives each of the six tile types'
// bands its own colours and shows their bevels.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.8> }
camera { location <0, 7, -6> look_at <0, 0, 1.5> angle 60 }
light_source { <-5, 30, -10> color rgb 1 }
plane { y, 0
  pigment { tiling 25
    color_map { [0 rgb <0.9, 0.2, 0.1>] [1/6 rgb <0.95, 0.95, 0.3>]
                [1/6 rgb <0.1, 0.6, 0.3>] [2/6 rgb <0.2, 0.8, 0.9>]
                [2/6 rgb <0.1, 0.3, 0.9>] [3/6 rgb <0.9, 0.9, 0.9>]
                [3/6 rgb <0.6, 0.1, 0.6>] [4/6 rgb <0.95, 0.6, 0.2>]
                [4/6 rgb <0.3, 0.3, 0.1>] [5/6 rgb <0.7, 0.9, 0.5>]
                [5/6 rgb <0.1, 0.1, 0.3>] [1 rgb <0.9, 0.5, 0.6>] }
    scale 0.9 rotate y*8 translate <0.3, 0, 0.2> }
  finish { ambient 0.3 diffuse 0.7 }
}
