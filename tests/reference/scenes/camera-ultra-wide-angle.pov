// Camera fidelity: the ultra_wide_angle projection.
#version 3.7;
#include "objects.inc"
camera { ultra_wide_angle location <0, 0.5, -0.5> look_at <0, 0.5, 1> angle 170 }
