// Camera fidelity: the omnimax projection.
#version 3.7;
#include "objects.inc"
camera { omnimax location <0, 0.5, 0> look_at <0, 0.5, 1> angle 200 }
