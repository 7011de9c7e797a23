#version 3.7;
#declare S = sphere { 0, 1 }
#declare N = <0, 0, 0>;
#declare Hit = trace(S, <0, 0, -5>, <0, 0, 1>, N);
#debug concat("Hit = <", vstr(3, Hit, ", ", 0, 6), ">\n")
#debug concat("N = <", vstr(3, N, ", ", 0, 6), ">\n")
