#version 3.7;
#macro Half(A) (A / 2) #end
#debug concat("<Half(1), Half(2), Half(3)> = <", vstr(3, <Half(1), Half(2), Half(3)>, ", ", 0, 1), ">\n")
