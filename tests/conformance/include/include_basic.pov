#version 3.7;
#include "include_defs.inc"
#debug concat("Defined_In_Include = ", str(Defined_In_Include, 0, 0), "\n")
