#version 3.7;
#debug concat("<1, 2, 3, 4, 5> = <", vstr(5, <1, 2, 3, 4, 5>, ", ", 0, 1), ">\n")
