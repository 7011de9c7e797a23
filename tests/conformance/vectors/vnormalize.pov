#version 3.7;
#debug concat("vnormalize(<3,4,0>) = <", vstr(3, vnormalize(<3,4,0>), ", ", 0, 6), ">\n")
#debug concat("vnormalize(<1,1,1>) = <", vstr(3, vnormalize(<1,1,1>), ", ", 0, 9), ">\n")
#debug concat("vnormalize(-5*y) = <", vstr(3, vnormalize(-5*y), ", ", 0, 6), ">\n")
