#version 3.7;
#debug "first\n"
#warning "middle"
#debug "last\n"
