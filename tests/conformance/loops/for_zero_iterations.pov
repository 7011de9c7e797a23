#version 3.7;
#for (I, 5, 1) #debug "never\n" #end
#debug "done\n"
