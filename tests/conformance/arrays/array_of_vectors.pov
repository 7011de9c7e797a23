#version 3.7;
#declare P = array[2] {<1, 2, 3>, <4, 5, 6>};
#debug concat("P[0] + P[1] = <", vstr(3, P[0] + P[1], ", ", 0, 0), ">\n")
#debug concat("P[1].y = ", str(P[1].y, 0, 0), "\n")
