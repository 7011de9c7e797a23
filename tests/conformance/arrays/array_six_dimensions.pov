#version 3.7;
#debug "before\n"
#declare A = array[1][1][1][1][1][1];
