#version 3.7;
#debug concat("<1, 2.5, -3> = <", vstr(3, <1, 2.5, -3>, ", ", 0, 2), ">\n")
