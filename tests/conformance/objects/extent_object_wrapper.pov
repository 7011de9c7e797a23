#version 3.7;
#declare S = sphere { 0, 1 }
#declare O = object { S scale 3 }
#debug concat("min_extent(O) = <", vstr(3, min_extent(O), ", ", 0, 6), ">\n")
#debug concat("max_extent(O) = <", vstr(3, max_extent(O), ", ", 0, 6), ">\n")
