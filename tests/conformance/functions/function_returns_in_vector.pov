#version 3.7;
#declare F = function { x * 2 }
#debug concat("<F(1, 0, 0), F(2, 0, 0), F(3, 0, 0)> = <", vstr(3, <F(1, 0, 0), F(2, 0, 0), F(3, 0, 0)>, ", ", 0, 1), ">\n")
