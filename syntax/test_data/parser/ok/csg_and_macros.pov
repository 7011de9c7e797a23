#version 3.7;
#include "colors.inc"

global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 1, 0> angle 40 right x*image_width/image_height }
light_source { <10, 20, -10> color White shadowless }

#macro Post(Height, optional Radius)
  #ifndef (Radius) #local Radius = 0.1; #end
  cylinder { 0, Height*y, Radius }
#end

difference {
  box { -1, 1 }
  sphere { 0, 1.3 }
  union {
    #for (I, 0, 3)
      object { Post(2) translate <I - 1.5, -1, 0> }
    #end
  }
  pigment { checker color Red, color Blue scale 0.25 }
  finish { specular 0.6 roughness 0.01 reflection { 0.1, 0.5 fresnel on } }
  rotate <0, 30, 0>
}
