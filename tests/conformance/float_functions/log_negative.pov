#version 3.7;
#debug "before\n"
#declare A = log(-2);
#debug "after\n"
