#version 3.7;
#debug "caf\u00e9\n"
