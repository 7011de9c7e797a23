#version 3.7;
#if (0) #debug "a\n" #elseif (1) #debug "b\n" #elseif (1) #debug "c\n" #else #debug "d\n" #end
