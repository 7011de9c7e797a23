#version 3.7;
#if (-0.5) #debug "true\n" #else #debug "false\n" #end
