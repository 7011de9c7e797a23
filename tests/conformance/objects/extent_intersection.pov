#version 3.7;
#declare I = intersection { sphere { 0, 1 } box { <0, 0, 0>, <2, 2, 2> } }
#debug concat("min_extent(I) = <", vstr(3, min_extent(I), ", ", 0, 6), ">\n")
#debug concat("max_extent(I) = <", vstr(3, max_extent(I), ", ", 0, 6), ">\n")
