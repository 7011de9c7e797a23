camera { location <0, 2, -3> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { <0, 1, 2>, 2 texture { pigment { color Yellow } } }
global_settings { assumed_gamma 1.0 radiosity { count 100 } }
background { color rgbt <0, 0, 0, 1> }
