#version 3.7;
#debug concat("vrotate(x, <0,0,90>) = <", vstr(3, vrotate(x, <0,0,90>), ", ", 0, 6), ">\n")
#debug concat("vrotate(x, <0,90,0>) = <", vstr(3, vrotate(x, <0,90,0>), ", ", 0, 6), ">\n")
#debug concat("vrotate(y, <90,0,0>) = <", vstr(3, vrotate(y, <90,0,0>), ", ", 0, 6), ">\n")
