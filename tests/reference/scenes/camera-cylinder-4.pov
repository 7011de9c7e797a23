// Camera fidelity: the cylinder 4 projection.
#version 3.7;
#include "objects.inc"
camera { cylinder 4 location <0, 0.5, -6> look_at <0, 0.5, 1> angle 90 right 8*x }
