#version 3.7;
#declare U = union { sphere { 0, 1 } box { <2, 2, 2>, <3, 4, 5> } }
#debug concat("min_extent(U) = <", vstr(3, min_extent(U), ", ", 0, 6), ">\n")
#debug concat("max_extent(U) = <", vstr(3, max_extent(U), ", ", 0, 6), ">\n")
