#version 3.7;
#if (0) #declare A = Undefined_Thing + 1; #debug "no\n" #else #debug "skipped bad code\n" #end
