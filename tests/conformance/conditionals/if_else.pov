#version 3.7;
#if (2 < 1) #debug "then\n" #else #debug "else\n" #end
