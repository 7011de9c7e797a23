// looks_like and projected_through. A lamp: a glowing bulb and shade shaped by
// looks_like, placed and turned with the light, letting its light out (the light casts the
// post's shadow). A light projected through a plate with a round and a square hole lights
// the floor in two patches; the ball inside one casts a shadow, and the ball between the
// light and the plate casts none.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.12, 0.15> }
camera { location <0, 5, -9> look_at <0, 0.5, 0.5> angle 50 }
light_source { <0, 0, 0> color rgb <1, 0.85, 0.6>
  looks_like {
    union {
      sphere { 0, 0.25 pigment { rgb <1, 0.95, 0.7> } finish { ambient 1 diffuse 0 } }
      cone { <0, 0.1, 0>, 0.2, <0, -0.3, 0>, 0.45 open
        pigment { rgb <0.9, 0.3, 0.2> } finish { ambient 0.4 } }
    }
  }
  rotate z*-20 translate <-2.6, 2.2, -1>
}
light_source { <1, 9, 2> color rgb 0.9
  projected_through {
    difference {
      box { <-1.5, -0.05, -1.5>, <1.5, 0.05, 1.5> }
      cylinder { <-0.7, -1, 0>, <-0.7, 1, 0>, 0.5 }
      box { <0.2, -1, -0.6>, <1.1, 1, 0.6> }
      translate <1, 4.5, 2>
    }
  }
}
sphere { <1.3, 7, 2>, 0.4 pigment { rgb 1 } }
plane { y, 0 pigment { rgb 0.8 } }
box { <-1.5, 0, -0.5>, <-1.2, 1.6, -0.2> pigment { rgb <0.4, 0.6, 0.9> } }
sphere { <1.6, 0.35, 2>, 0.35 pigment { rgb <0.9, 0.4, 0.3> } }
