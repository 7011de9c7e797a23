#version 3.7;
#include "glass.inc"
#debug concat("Col_Glass_Clear = <", vstr(5, Col_Glass_Clear, ", ", 0, 6), ">\n")
#debug concat("Col_Ruby_01 = <", vstr(5, Col_Ruby_01, ", ", 0, 6), ">\n")
