sphere { 0, 1 }
= = =
camera { location <0, 1, -3> ] look_at 0 }
} 
light_source { 0 color rgb 1 }
