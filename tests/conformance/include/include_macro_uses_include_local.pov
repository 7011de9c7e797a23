#version 3.7;
#include "include_macro_local.inc"
#debug concat("Uses_Local() = ", str(Uses_Local(), 0, 0), "\n")
