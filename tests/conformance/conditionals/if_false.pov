#version 3.7;
#if (0) #debug "taken\n" #end
#debug "done\n"
