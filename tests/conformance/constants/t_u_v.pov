#version 3.7;
#debug concat("t = <", vstr(4, t, ", ", 0, 0), ">\n")
#debug concat("u = <", vstr(2, u, ", ", 0, 0), ">\n")
#debug concat("v = <", vstr(2, v, ", ", 0, 0), ">\n")
