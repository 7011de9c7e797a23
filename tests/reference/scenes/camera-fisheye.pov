// Camera fidelity: the fisheye projection.
#version 3.7;
#include "objects.inc"
camera { fisheye location <0, 0.5, 0> look_at <0, 0.5, 1> angle 200 }
