#version 3.7;
#debug "before\n"
#declare A = array[3] {1, 2};
