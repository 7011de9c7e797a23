#version 3.7;
#macro Make(V) #declare V = 3; #end
Make(Brand_New)
#debug "after\n"
