#version 3.7;
#declare F = function { transform { rotate <90, 0, 0> scale 4 } }
#debug concat("F(4, 3, 7) = <", vstr(3, F(4, 3, 7), ", ", 0, 6), ">\n")
