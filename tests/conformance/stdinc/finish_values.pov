#version 3.7;
#include "finish.inc"
#debug "finish.inc loaded\n"
#declare Fin = finish { Dull }
#debug "finish used\n"
