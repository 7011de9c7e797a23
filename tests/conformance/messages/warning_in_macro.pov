#version 3.7;
#macro Warn(S) #warning S #end
Warn("from macro")
#debug "done\n"
