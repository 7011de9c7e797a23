#version 3.7;
#debug "before\n"
#declare A = sor { 5, <0, 0> <1, 1> <1, 2> <1, 1.5> <0, 3> }
#debug "after\n"
