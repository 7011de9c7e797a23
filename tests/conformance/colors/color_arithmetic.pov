#version 3.7;
#declare A = rgb <1, 0.5, 0.2>;
#declare B = rgbf <0.5, 0.5, 0.5, 1>;
#debug concat("A*0.9 = <", vstr(5, A*0.9, ", ", 0, 3), ">\n")
#debug concat("A+B = <", vstr(5, A+B, ", ", 0, 3), ">\n")
#debug concat("A*B = <", vstr(5, A*B, ", ", 0, 3), ">\n")
