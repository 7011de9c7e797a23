#version 3.7;
// stage1.inc's camera, light and floor with a sphere on it.
#include "stage1.inc"
global_settings { assumed_gamma 1 }
sphere { 0, 2 texture { Jade } }
