#version 3.7;
#declare R = seed(17);
#declare V = <rand(R), rand(R), rand(R)>;
#debug concat("V = <", vstr(3, V, ", ", 0, 12), ">\n")
