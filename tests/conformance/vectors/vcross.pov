#version 3.7;
#debug concat("vcross(x, y) = <", vstr(3, vcross(x, y), ", ", 0, 1), ">\n")
#debug concat("vcross(y, x) = <", vstr(3, vcross(y, x), ", ", 0, 1), ">\n")
#debug concat("vcross(<1,2,3>, <4,5,6>) = <", vstr(3, vcross(<1,2,3>, <4,5,6>), ", ", 0, 1), ">\n")
