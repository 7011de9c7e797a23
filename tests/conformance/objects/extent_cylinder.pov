#version 3.7;
#declare C = cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 }
#debug concat("min_extent(C) = <", vstr(3, min_extent(C), ", ", 0, 6), ">\n")
#debug concat("max_extent(C) = <", vstr(3, max_extent(C), ", ", 0, 6), ">\n")
