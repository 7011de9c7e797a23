#version 3.7;
#include "include_macro.inc"
#debug concat("Twice(21) = ", str(Twice(21), 0, 0), "\n")
