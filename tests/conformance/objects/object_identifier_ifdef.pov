#version 3.7;
#declare S = sphere { 0, 1 }
#ifdef (S) #debug "object declared\n" #end
