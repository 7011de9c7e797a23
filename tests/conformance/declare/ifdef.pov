#version 3.7;
#declare A = 1;
#ifdef (A) #debug "A defined\n" #end
#ifdef (B) #debug "B defined\n" #else #debug "B undefined\n" #end
