#version 3.7;
#include "colors.inc"
#debug concat("MediumAquamarine = <", vstr(5, MediumAquamarine, ", ", 0, 6), ">\n")
#debug concat("Scarlet = <", vstr(5, Scarlet, ", ", 0, 6), ">\n")
#debug concat("NewTan = <", vstr(5, NewTan, ", ", 0, 6), ">\n")
#debug concat("VeryDarkBrown = <", vstr(5, VeryDarkBrown, ", ", 0, 6), ">\n")
#debug concat("Quartz = <", vstr(5, Quartz, ", ", 0, 6), ">\n")
#debug concat("SummerSky = <", vstr(5, SummerSky, ", ", 0, 6), ">\n")
