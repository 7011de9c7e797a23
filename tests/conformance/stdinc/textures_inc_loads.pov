#version 3.7;
#include "colors.inc"
#include "textures.inc"
#debug "textures.inc loaded\n"
