#version 3.7;
#include "shapes.inc"
#debug "shapes.inc loaded\n"
