#version 3.7;
#warning "careful"
#debug "after warning\n"
