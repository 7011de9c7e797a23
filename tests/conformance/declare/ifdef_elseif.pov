#version 3.7;
#declare B = 0;
#ifdef (A) #debug "A\n" #elseif (B) #debug "B true\n" #elseif (1) #debug "fallback\n" #else #debug "else\n" #end
