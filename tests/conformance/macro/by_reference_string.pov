#version 3.7;
#macro Append(S) #declare S = concat(S, "!"); #end
#declare Msg = "hey";
Append(Msg)
Append(Msg)
#debug concat("Msg = [", Msg, "]\n")
