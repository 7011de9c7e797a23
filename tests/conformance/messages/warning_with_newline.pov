#version 3.7;
#warning "two\nlines"
#debug "after warning\n"
