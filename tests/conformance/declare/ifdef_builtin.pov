#version 3.7;
#ifdef (pi) #debug "pi defined\n" #else #debug "pi undefined\n" #end
#ifdef (x) #debug "x defined\n" #else #debug "x undefined\n" #end
