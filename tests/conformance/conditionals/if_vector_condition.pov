#version 3.7;
#debug "before\n"
#if (<1,1,1>) #debug "vector\n" #end
