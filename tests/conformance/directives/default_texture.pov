#version 3.7;
#default { texture { pigment { rgb <1,0,0> } finish { diffuse 0.5 } } }
#debug "default texture accepted\n"
