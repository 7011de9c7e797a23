#version 3.7;
#declare B = box { <3, 4, 5>, <-1, 0, 2> }
#debug concat("min_extent(B) = <", vstr(3, min_extent(B), ", ", 0, 6), ">\n")
#debug concat("max_extent(B) = <", vstr(3, max_extent(B), ", ", 0, 6), ">\n")
