#version 3.7;
#include "include_outer.inc"
#debug concat("Outer_Value + Inner_Value = ", str(Outer_Value + Inner_Value, 0, 0), "\n")
