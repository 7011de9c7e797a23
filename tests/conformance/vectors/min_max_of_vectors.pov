#version 3.7;
#debug "before\n"
#debug concat("min(<1,5,3>, <4,2,6>) = <", vstr(3, min(<1,5,3>, <4,2,6>), ", ", 0, 1), ">\n")
