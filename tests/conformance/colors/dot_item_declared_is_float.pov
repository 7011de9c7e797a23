#version 3.7;
#declare C = rgb <0.7, 0, 0.3>;
#declare V = C.red;
#debug concat("V: ", str(V, 0, 6), " ", str(V * 2, 0, 6), "\n")
#declare X = V + <0, 1, 0>;
#debug concat("X: ", vstr(3, X, ", ", 0, 3), "\n")
#macro Show(Value) #debug concat("arg: ", str(Value, 0, 6), "\n") #end
Show(C.red)
Show(C.blue)
