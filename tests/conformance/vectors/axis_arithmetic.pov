#version 3.7;
#debug concat("5*x = <", vstr(3, 5*x, ", ", 0, 0), ">\n")
#debug concat("x+y+z = <", vstr(3, x+y+z, ", ", 0, 0), ">\n")
#debug concat("2*x-3*z = <", vstr(3, 2*x-3*z, ", ", 0, 0), ">\n")
