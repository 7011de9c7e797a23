#version 3.7;
#debug "before\n"
#declare F = function { x + Nothing }
