#version 3.7;
#debug concat("<1, 2> = <", vstr(2, <1, 2>, ", ", 0, 1), ">\n")
