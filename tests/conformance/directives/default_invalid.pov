#version 3.7;
#debug "before\n"
#default { sphere { 0, 1 } }
