// Focal blur fidelity: a near sphere in focus, a box and a far column out of focus, on a
// checkered floor. Blur is stochastic in POV-Ray too, so tests/tests/fidelity.rs compares
// the pictures after a box blur, at the level a viewer sees.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.45, 0.55, 0.75> }
camera {
  location <0, 1.5, -9> look_at <0, 0, 0> angle 45
  focal_point <0.7, -0.4, -5> aperture 0.6 blur_samples 24
}
light_source { <6, 25, -20> color rgb 1 }
light_source { <-8, 20, -25> color rgb 0.6 }
plane { y, -1 pigment { checker rgb 0.85, rgb 0.25 } }
sphere { <0.7, -0.4, -5>, 0.6 pigment { rgb <0.95, 0.45, 0.35> } finish { phong 0.7 } }
box { <-1.2, -1, -1.2>, <1.2, 1.4, 1.2> rotate y*25 pigment { rgb <0.35, 0.8, 0.4> } }
cylinder { <-5, -1, 18>, <-5, 7, 18>, 2 pigment { rgb <0.3, 0.35, 0.95> } }
