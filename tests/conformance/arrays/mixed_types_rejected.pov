#version 3.7;
#declare A = array[2];
#declare A[0] = 1;
#debug "before\n"
#declare A[1] = "text";
#debug "after\n"
