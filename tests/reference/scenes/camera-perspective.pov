// Camera fidelity: the perspective projection.
#version 3.7;
#include "objects.inc"
camera { perspective location <0, 3, -7> look_at <0, 0, 1> angle 60 }
