#version 3.7;
#declare A = 1;
#undef A
#ifdef (A) #debug "defined\n" #else #debug "undefined\n" #end
