#version 3.7;
#macro IsBig(A) (A > 10) #end
#if (IsBig(20)) #debug "big\n" #end
#if (IsBig(5)) #debug "wrong\n" #else #debug "small\n" #end
