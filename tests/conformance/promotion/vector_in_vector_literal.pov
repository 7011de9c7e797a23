#version 3.7;
#debug "before\n"
#debug concat("<<1,2>, 3> = <", vstr(3, <<1,2>, 3>, ", ", 0, 1), ">\n")
