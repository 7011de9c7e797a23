// Camera fidelity: the panoramic projection.
#version 3.7;
#include "objects.inc"
camera { panoramic location <0, 0.5, 0> look_at <0, 0.5, 1> }
