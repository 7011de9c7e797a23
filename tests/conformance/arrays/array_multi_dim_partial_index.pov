#version 3.7;
#declare G = array[2][2] {{1, 2}, {3, 4}};
#debug "before\n"
#debug concat("G[1] = ", str(G[1], 0, 0), "\n")
