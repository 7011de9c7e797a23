// Subsurface light transport: a marble sphere with the coefficients Jensen, Marschner,
// Levoy and Hanrahan measured (2001; translucency = 1/σ's in mm, pigment = diffuse
// reflectance) and a thin slab of wax lit from behind, glowing where the light passes
// through it. The objects float before a plain background: POV-Ray's subsurface samples
// also pick up light from other objects behind a translucent one, which we do not model.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 10
  subsurface { samples 50, 50 }
}
background { rgb <0.12, 0.14, 0.18> }
camera { location <0, 1.2, -5> look_at <0, 0.7, 0> angle 42 }
light_source { <3, 5, 6> rgb 1.1 }
light_source { <-4, 4, -5> rgb 0.35 }
sphere { <-0.9, 0.8, 0>, 0.8
  pigment { rgb <0.83, 0.79, 0.75> }
  finish { ambient 0.05 diffuse 0.8 specular 0.3 roughness 0.02
           subsurface { translucency <0.4566, 0.3817, 0.3333> } }
  interior { ior 1.5 }
}
box { <-0.6, 0, -0.06>, <0.6, 1.4, 0.06>
  pigment { rgb <0.9, 0.55, 0.2> }
  finish { ambient 0.05 diffuse 0.9 subsurface { translucency <1.5, 0.9, 0.3> } }
  interior { ior 1.45 }
  rotate y * -25
  translate <1.1, 0, 0.2>
}
