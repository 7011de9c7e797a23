#version 3.7;
#declare T = transform { rotate 90*z }
#declare F = function { transform { T } }
#debug concat("F(1, 0, 0) = <", vstr(3, F(1, 0, 0), ", ", 0, 6), ">\n")
