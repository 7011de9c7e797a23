#version 3.7;
#debug concat("vrotate(<1,2,3>, <30,45,60>) = <", vstr(3, vrotate(<1,2,3>, <30,45,60>), ", ", 0, 9), ">\n")
#debug concat("x then y then z = <", vstr(3, vrotate(vrotate(vrotate(<1,2,3>, 30*x), 45*y), 60*z), ", ", 0, 9), ">\n")
