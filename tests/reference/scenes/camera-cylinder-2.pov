// Camera fidelity: the cylinder 2 projection.
#version 3.7;
#include "objects.inc"
camera { cylinder 2 location <0, 0.5, -6> look_at <0, 0.5, 1> angle 90 }
