#version 3.7;
#debug ""
#debug "after empty\n"
