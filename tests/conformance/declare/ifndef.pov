#version 3.7;
#declare A = 1;
#ifndef (A) #debug "A undefined\n" #else #debug "A defined\n" #end
#ifndef (B) #debug "B undefined\n" #end
