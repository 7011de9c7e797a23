#version 3.7;
#debug "before\n"
#if ("a") #debug "string\n" #end
