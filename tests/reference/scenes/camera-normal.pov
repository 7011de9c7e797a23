// Camera fidelity: a normal on the camera bends every ray, sampled on the image plane
// (onion rings about the picture's centre, one ring per 0.15 of the image's width).
#version 3.7;
#include "objects.inc"
camera {
  perspective location <0, 3, -7> look_at <0, 0, 1> angle 60
  normal { onion 0.3 sine_wave scale 0.15 translate <0.1, 0.05, 0> }
}
