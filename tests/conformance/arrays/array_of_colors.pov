#version 3.7;
#declare C = array[2] {rgb <1, 0, 0>, rgbt <0, 1, 0, 0.5>};
#debug concat("C[1] = <", vstr(5, C[1], ", ", 0, 2), ">\n")
