#version 3.7;
#declare Shared = 1;
#include "include_shadow.inc"
#debug concat("after include: ", str(Shared, 0, 0), "\n")
