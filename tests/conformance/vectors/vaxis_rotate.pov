#version 3.7;
#debug concat("vaxis_rotate(x, y, 90) = <", vstr(3, vaxis_rotate(x, y, 90), ", ", 0, 6), ">\n")
#debug concat("vaxis_rotate(<1,2,3>, <1,1,1>, 120) = <", vstr(3, vaxis_rotate(<1,2,3>, <1,1,1>, 120), ", ", 0, 6), ">\n")
#debug concat("vaxis_rotate(<1,0,0>, <0,0,2>, 45) = <", vstr(3, vaxis_rotate(<1,0,0>, <0,0,2>, 45), ", ", 0, 9), ">\n")
