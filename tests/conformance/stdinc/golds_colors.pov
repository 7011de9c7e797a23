#version 3.7;
#include "golds.inc"
#debug concat("P_Gold1 = <", vstr(5, P_Gold1, ", ", 0, 6), ">\n")
#debug concat("P_Gold5 = <", vstr(5, P_Gold5, ", ", 0, 6), ">\n")
