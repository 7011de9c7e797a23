// Blob fidelity: spheres merging, a cylinder component, a negative component denting
// another, an unevenly scaled component, and components with textures of their own
// blended where they merge.
#version 3.7;
#declare S = 1;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 4, -8>*S look_at <0, 0.5, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.5*S pigment { rgb 0.7 } }
blob { threshold 0.6
  sphere { <.75, 0, 0>, 1, 1 }
  sphere { <-.375, .64952, 0>, 1, 1 }
  sphere { <-.375, -.64952, 0>, 1, 1 }
  scale 0.8 translate <-2.3, 0.7, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
blob { threshold 0.5
  cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.7, 1 }
  sphere { <0, 0.5, 0>, 0.8, strength -1.5 }
  sphere { <0.9, 0, 0>, 0.8, 1 scale <1, 2, 1> }
  rotate y*30 translate <0.6, 0.3, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
blob { threshold 0.3
  component 1, 0.9, <0, 0, 0>
  component 1, 0.9, <0, 0.9, 0>
  sturm translate <2.8, 0, 0.5> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
blob { threshold 0.5
  sphere { <-0.5, 0, 0>, 0.9, 1 pigment { rgb <1, 0.9, 0.2> } }
  sphere { <0.5, 0, 0>, 0.9, 1 pigment { rgb <0.7, 0.2, 0.9> } finish { specular 0.1 } }
  cylinder { <0, 0, 0>, <0, 0.9, 0>, 0.5, 0.8 }
  translate <0, -0.1, -2.2> scale S pigment { rgb <0.2, 0.8, 0.8> } finish { F } }
