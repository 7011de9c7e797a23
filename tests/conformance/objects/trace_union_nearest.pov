#version 3.7;
#declare U = union { sphere { <0, 0, 5>, 1 } sphere { <0, 0, 2>, 0.5 } }
#declare Hit = trace(U, <0, 0, -5>, z);
#debug concat("Hit = <", vstr(3, Hit, ", ", 0, 6), ">\n")
