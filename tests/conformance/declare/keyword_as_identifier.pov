#version 3.7;
#debug "before\n"
#declare sphere = 1;
