#version 3.7;
#include "strings.inc"
#declare V = Parse_String("<1, 2, 3> * 2");
#debug concat("V = <", vstr(3, V, ", ", 0, 1), ">\n")
