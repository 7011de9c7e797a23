#version 3.7;
#macro M() #end
#ifdef (M) #debug "macro defined\n" #end
#undef M
#ifndef (M) #debug "macro undefined\n" #end
