#version 3.7;
#debug concat("-<1,-2,3> = <", vstr(3, -<1,-2,3>, ", ", 0, 1), ">\n")
#debug concat("-(x+y) = <", vstr(3, -(x+y), ", ", 0, 1), ">\n")
