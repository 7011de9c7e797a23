#version 3.7;
#debug "before\n"
#declare A = Missing + 1;
