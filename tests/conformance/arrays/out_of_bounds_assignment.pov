#version 3.7;
#declare A = array[3];
#debug "before\n"
#declare A[5] = 1;
