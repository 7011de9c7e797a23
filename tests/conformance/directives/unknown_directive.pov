#version 3.7;
#debug "before\n"
#frobnicate
