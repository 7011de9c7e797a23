#version 3.7;
#macro Mid(A, B) ((A + B) / 2) #end
#debug concat("Mid(<0,0,0>, <2,4,6>) = <", vstr(3, Mid(<0,0,0>, <2,4,6>), ", ", 0, 1), ">\n")
