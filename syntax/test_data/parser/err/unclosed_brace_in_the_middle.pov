camera { location <0, 2, -5> look_at 0 }
union {
  sphere { 0, 1
    pigment { Red }
  box { 0, 1 }
}
light_source { <10, 20, -10> color rgb 1 }
plane { y, 0 }
