#version 3.7;
#include "strings.inc"
#declare T = Triangle_Str(<0, 0, 0>, <1, 0, 0>, <0, 1, 0>);
#debug concat("strlen(T) = ", str(strlen(T), 0, 0), "\n")
#debug concat("head = [", substr(T, 1, 50), "]\n")
#debug concat("tail = [", substr(T, 51, strlen(T) - 50), "]\n")
