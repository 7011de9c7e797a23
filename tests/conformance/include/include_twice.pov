#version 3.7;
#declare Times = 0;
#include "include_counter.inc"
#include "include_counter.inc"
#debug concat("Times = ", str(Times, 0, 0), "\n")
