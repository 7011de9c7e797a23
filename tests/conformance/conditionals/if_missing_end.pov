#version 3.7;
#debug "before\n"
#if (1) #debug "inside\n"
