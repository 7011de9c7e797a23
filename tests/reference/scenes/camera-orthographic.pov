// Camera fidelity: the orthographic projection.
#version 3.7;
#include "objects.inc"
camera { orthographic location <0, 3, -7> look_at <0, 0, 1> right 12*x up 9*y }
