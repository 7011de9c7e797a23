#version 3.7;
#debug "before\n"
#include "no_such_file.inc"
