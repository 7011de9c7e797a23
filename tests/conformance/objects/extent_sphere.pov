#version 3.7;
#declare S = sphere { <1, 2, 3>, 2 }
#debug concat("min_extent(S) = <", vstr(3, min_extent(S), ", ", 0, 6), ">\n")
#debug concat("max_extent(S) = <", vstr(3, max_extent(S), ", ", 0, 6), ">\n")
