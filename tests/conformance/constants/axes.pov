#version 3.7;
#debug concat("x = <", vstr(3, x, ", ", 0, 0), ">\n")
#debug concat("y = <", vstr(3, y, ", ", 0, 0), ">\n")
#debug concat("z = <", vstr(3, z, ", ", 0, 0), ">\n")
#debug concat("-x = <", vstr(3, -x, ", ", 0, 0), ">\n")
