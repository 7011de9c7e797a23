#version 3.7;
#debug "main before\n"
#include "include_prints.inc"
#debug "main after\n"
