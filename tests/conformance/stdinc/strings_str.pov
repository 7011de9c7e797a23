#version 3.7;
#include "strings.inc"
#debug concat("Str(pi) = [", Str(pi), "]\n")
#debug concat("VStr(<1, 2, 3>) = [", VStr(<1, 2, 3>), "]\n")
#debug concat("Vstr(<1, 2, 3>, 0, 2) = [", Vstr(<1, 2, 3>, 0, 2), "]\n")
#debug concat("VStr2D(<1, 2>) = [", VStr2D(<1, 2>), "]\n")
