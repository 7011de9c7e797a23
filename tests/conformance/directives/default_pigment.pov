#version 3.7;
#default { pigment { rgb 0.5 } }
#debug "default pigment accepted\n"
