#version 3.7;
#include "include_locals.inc"
#ifdef (Include_Local) #debug "local leaked\n" #else #debug "local gone\n" #end
#debug concat("Include_Global = ", str(Include_Global, 0, 0), "\n")
