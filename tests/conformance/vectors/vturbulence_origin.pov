#version 3.7;
#debug concat("A = <", vstr(3, vturbulence(2, 0.5, 6, <0,0,0>), ", ", 0, 9), ">\n")
#debug concat("B = <", vstr(3, vturbulence(3, 0.25, 3, <-1.5,7.25,0.3>), ", ", 0, 9), ">\n")
