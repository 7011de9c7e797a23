#version 3.7;
#declare Pl = plane { y, 0 }
#debug concat("min_extent(Pl) = <", vstr(3, min_extent(Pl), ", ", 0, 1), ">\n")
#debug concat("max_extent(Pl) = <", vstr(3, max_extent(Pl), ", ", 0, 1), ">\n")
