#version 3.7;
#debug concat("octaves 1 = <", vstr(3, vturbulence(2, 0.5, 1, <0.3,0.6,0.9>), ", ", 0, 9), ">\n")
#debug concat("octaves 2 = <", vstr(3, vturbulence(2, 0.5, 2, <0.3,0.6,0.9>), ", ", 0, 9), ">\n")
#debug concat("octaves 3 = <", vstr(3, vturbulence(2, 0.5, 3, <0.3,0.6,0.9>), ", ", 0, 9), ">\n")
#debug concat("octaves 10 = <", vstr(3, vturbulence(2, 0.5, 10, <0.3,0.6,0.9>), ", ", 0, 9), ">\n")
