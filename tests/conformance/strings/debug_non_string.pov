#version 3.7;
#debug "before\n"
#debug 5
