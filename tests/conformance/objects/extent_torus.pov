#version 3.7;
#declare T = torus { 2, 0.5 }
#debug concat("min_extent(T) = <", vstr(3, min_extent(T), ", ", 0, 6), ">\n")
#debug concat("max_extent(T) = <", vstr(3, max_extent(T), ", ", 0, 6), ">\n")
