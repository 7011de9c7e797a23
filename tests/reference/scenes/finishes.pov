// Finish fidelity: ambient, emission, diffuse, brilliance, phong and phong_size,
// specular and roughness, metallic highlights, side by side.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 0.9, 0.8> }
background { color rgb 0.15 }
camera { location <0, 0, -12> look_at 0 angle 50 }
light_source { <-6, 8, -10> color rgb 1 }
light_source { <8, -2, -6> color rgb 0.4 }
#declare P = pigment { rgb <0.8, 0.45, 0.2> }
sphere { <-4.5, 2.2, 0>, 1 pigment { P } finish { ambient 0.6 diffuse 0.2 } }
sphere { <-1.5, 2.2, 0>, 1 pigment { P } finish { ambient 0 emission 0.3 diffuse 0.5 } }
sphere { < 1.5, 2.2, 0>, 1 pigment { P } finish { diffuse 0.9 brilliance 3 } }
sphere { < 4.5, 2.2, 0>, 1 pigment { P } finish { diffuse 0.5 brilliance 0.4 } }
sphere { <-4.5, -0.5, 0>, 1 pigment { P } finish { phong 0.9 } }
sphere { <-1.5, -0.5, 0>, 1 pigment { P } finish { phong 0.9 phong_size 200 } }
sphere { < 1.5, -0.5, 0>, 1 pigment { P } finish { specular 0.8 roughness 0.1 } }
sphere { < 4.5, -0.5, 0>, 1 pigment { P } finish { specular 1 roughness 0.002 } }
sphere { <-3, -3.2, 0>, 1 pigment { P } finish { phong 1 metallic } }
sphere { < 0, -3.2, 0>, 1 pigment { P } finish { specular 1 roughness 0.02 metallic 0.5 } }
sphere { < 3, -3.2, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0 diffuse 1 } }
