#version 3.7;
// S_Cloud4 of skies.inc, looking up and towards the horizon.
#include "colors.inc"
#include "skies.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 0, 0> look_at <0, 0.4, 1> angle 100 }
sky_sphere { S_Cloud4 }
