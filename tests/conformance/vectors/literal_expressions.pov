#version 3.7;
#declare A = 2;
#debug concat("<A*2, A-1, A/4> = <", vstr(3, <A*2, A-1, A/4>, ", ", 0, 2), ">\n")
