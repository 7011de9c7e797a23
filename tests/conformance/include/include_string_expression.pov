#version 3.7;
#declare Name = "defs";
#include concat("include_", Name, ".inc")
#debug concat("Defined_In_Include = ", str(Defined_In_Include, 0, 0), "\n")
