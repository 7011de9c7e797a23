#version 3.7;
#macro Double(V) #declare V = V * 2; #end
#declare P = <1, 2, 3>;
Double(P)
#debug concat("P = <", vstr(3, P, ", ", 0, 1), ">\n")
