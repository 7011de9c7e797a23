#version 3.7;
#macro Define(V) #declare Made_By_Macro = V; #end
Define(<1, 2, 3>)
#debug concat("Made_By_Macro = <", vstr(3, Made_By_Macro, ", ", 0, 0), ">\n")
