#version 3.7;
#if (1e-11) #debug "true\n" #else #debug "false\n" #end
#if (1e-9) #debug "true\n" #else #debug "false\n" #end
