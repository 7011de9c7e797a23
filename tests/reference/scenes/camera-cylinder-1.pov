// Camera fidelity: the cylinder 1 projection.
#version 3.7;
#include "objects.inc"
camera { cylinder 1 location <0, 0.5, 0> look_at <0, 0.5, 1> angle 270 }
