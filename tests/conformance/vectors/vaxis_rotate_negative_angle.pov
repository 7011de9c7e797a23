#version 3.7;
#debug concat("vaxis_rotate(x, z, -30) = <", vstr(3, vaxis_rotate(x, z, -30), ", ", 0, 9), ">\n")
