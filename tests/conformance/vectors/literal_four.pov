#version 3.7;
#debug concat("<1, 2, 3, 4> = <", vstr(4, <1, 2, 3, 4>, ", ", 0, 1), ">\n")
