#version 3.7;
#debug "before\n"
#include "error_raiser.inc"
