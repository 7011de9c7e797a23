#version 3.7;
#declare B = box { -1, 1 }
#declare Hit = trace(B, <5, 0.5, 0.25>, -x);
#debug concat("Hit = <", vstr(3, Hit, ", ", 0, 6), ">\n")
