#version 3.7;
#debug "before\n"
#debug concat("vnormalize(<0,0,0>) = <", vstr(3, vnormalize(<0,0,0>), ", ", 0, 6), ">\n")
