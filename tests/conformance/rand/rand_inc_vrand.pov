#version 3.7;
#include "rand.inc"
#declare R = seed(8);
#debug concat("VRand(R) = <", vstr(3, VRand(R), ", ", 0, 9), ">\n")
#debug concat("in box = <", vstr(3, VRand_In_Box(<0,0,0>, <10,20,30>, R), ", ", 0, 9), ">\n")
