#version 3.7;
#if (1) #debug "taken\n" #end
#debug "done\n"
