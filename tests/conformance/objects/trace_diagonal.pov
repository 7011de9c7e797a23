#version 3.7;
#declare S = sphere { 0, 1 }
#declare Start = <1, 1, 1>;
#declare N = <0, 0, 0>;
#declare Hit = trace(S, Start, <0, 0, 0> - Start, N);
#debug concat("Hit = <", vstr(3, Hit, ", ", 0, 9), ">\n")
#debug concat("N = <", vstr(3, N, ", ", 0, 9), ">\n")
