#version 3.7;
#include "include_update.inc"
#debug concat("after: ", str(defined(Counter), 0, 0), "\n")
