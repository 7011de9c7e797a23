#version 3.7;
#debug "plain text\n"
