#version 3.7;
#declare S = sphere { 0, 1 translate <5, 0, 0> }
#debug concat("min_extent(S) = <", vstr(3, min_extent(S), ", ", 0, 6), ">\n")
#debug concat("max_extent(S) = <", vstr(3, max_extent(S), ", ", 0, 6), ">\n")
