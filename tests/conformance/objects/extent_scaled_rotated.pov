#version 3.7;
#declare B = box { -1, 1 scale <2, 1, 1> rotate 45*z }
#debug concat("min_extent(B) = <", vstr(3, min_extent(B), ", ", 0, 6), ">\n")
#debug concat("max_extent(B) = <", vstr(3, max_extent(B), ", ", 0, 6), ">\n")
