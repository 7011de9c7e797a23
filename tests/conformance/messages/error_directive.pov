#version 3.7;
#debug "before\n"
#error "stop here"
#debug "never\n"
