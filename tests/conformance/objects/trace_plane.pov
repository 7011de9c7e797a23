#version 3.7;
#declare Pl = plane { y, -1 }
#declare N = <0, 0, 0>;
#declare Hit = trace(Pl, <1, 5, 2>, <1, -1, 0>, N);
#debug concat("Hit = <", vstr(3, Hit, ", ", 0, 6), ">\n")
#debug concat("N = <", vstr(3, N, ", ", 0, 6), ">\n")
