#version 3.7;
#debug concat("A = <", vstr(3, vturbulence(2, 0.5, 6, <1,2,3>), ", ", 0, 9), ">\n")
#debug concat("B = <", vstr(3, vturbulence(2, 0.5, 1, <0.5,0.5,0.5>), ", ", 0, 9), ">\n")
