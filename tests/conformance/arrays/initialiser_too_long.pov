#version 3.7;
#debug "before\n"
#declare A = array[2] {1, 2, 3};
