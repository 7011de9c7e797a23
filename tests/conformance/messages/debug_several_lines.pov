#version 3.7;
#debug "line 1\nline 2\nline 3\n"
