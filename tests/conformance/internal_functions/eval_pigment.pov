#version 3.7;
#include "functions.inc"
#declare C = eval_pigment(pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } }, <0.25, 0, 0>);
#debug concat("C = <", vstr(5, C, ", ", 0, 6), ">\n")
