#version 3.7;
#debug "before\n"
#declare A = sqrt(-1);
#debug "after\n"
