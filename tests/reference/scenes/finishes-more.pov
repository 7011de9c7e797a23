// More finish fidelity: brilliance under two lights, a backside diffuse and
// double_illuminate on thin discs lit from behind.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { location <0, 1, -9> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 6, -6> color rgb 1 }
light_source { <3, 2, 8> color rgb <0.9, 0.8, 0.6> }
sphere { <-3, 0.5, 0>, 1.3 pigment { rgb 0.6 } finish { brilliance 2 specular 0.4 } }
sphere { <0, 0.5, 0>, 1.3 pigment { rgb <0.7, 0.7, 0.8> } finish { diffuse 0.6 phong 0.5 } }
disc { <2.8, 1.6, 0>, z, 1 pigment { rgb <0.9, 0.6, 0.2> } finish { diffuse 0.5, 0.4 } }
disc { <2.8, -0.8, 0>, z, 1 pigment { rgb <0.2, 0.6, 0.9> } double_illuminate }
