#version 3.7;
#declare C = rgb <0.2, 0.4, 0.6>;
#debug concat("<C.red, C.green, C.blue> = <", vstr(3, <C.red, C.green, C.blue>, ", ", 0, 2), ">\n")
