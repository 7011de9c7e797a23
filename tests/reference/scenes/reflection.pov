// Reflection fidelity: a mirror, variable reflection with falloff, Fresnel reflection,
// metallic reflection and a reflection exponent, over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
background { color rgb <0.5, 0.7, 0.9> }
camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.9, rgb 0.2 } finish { reflection 0.15 } }
sphere { <-4.5, 0.2, 0>, 1.2 pigment { rgb 0.1 } finish { reflection 0.9 ambient 0 diffuse 0.1 } }
sphere { <-1.5, 0.2, 0>, 1.2 pigment { rgb <0.2, 0.3, 0.6> } finish { reflection { 0.05, 1 falloff 3 } } }
sphere { < 1.5, 0.2, 0>, 1.2 pigment { rgb <0.6, 0.2, 0.2> } finish { reflection { 0, 1 fresnel } } interior { ior 1.5 } }
sphere { < 4.5, 0.2, 0>, 1.2 pigment { rgb <0.9, 0.7, 0.2> } finish { reflection { 0.8 metallic } diffuse 0.2 } }
box { <-6, -1, 3>, <6, 3, 3.5> pigment { rgb <0.3, 0.7, 0.4> } finish { reflection { 0.5 exponent 0.5 } } }
