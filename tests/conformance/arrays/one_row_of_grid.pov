#version 3.7;
#declare G = array[4][5];
#debug "before\n"
#declare Row = G[2];
