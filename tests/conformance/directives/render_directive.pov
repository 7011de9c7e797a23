#version 3.7;
#debug "before\n"
#render "render text\n"
#debug "after\n"
