#version 3.7;
#declare C = cone { <0, 0, 0>, 1, <0, 3, 0>, 0.5 }
#debug concat("min_extent(C) = <", vstr(3, min_extent(C), ", ", 0, 6), ">\n")
#debug concat("max_extent(C) = <", vstr(3, max_extent(C), ", ", 0, 6), ">\n")
