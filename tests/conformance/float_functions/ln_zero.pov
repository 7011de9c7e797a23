#version 3.7;
#debug "before\n"
#declare A = ln(0);
#debug "after\n"
