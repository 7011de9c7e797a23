#version 3.7;
// stdcam.inc's camera, light and plane with a sphere on the plane.
#include "colors.inc"
#include "stdcam.inc"
global_settings { assumed_gamma 1 }
sphere { <-0.5, 0.5, 0>, 0.5 pigment { rgb <0.2, 0.5, 0.9> } }
