// Camera fidelity: the cylinder 3 projection.
#version 3.7;
#include "objects.inc"
camera { cylinder 3 location <0, 0.5, 0> look_at <0, 0.5, 1> angle 270 up 4*y }
