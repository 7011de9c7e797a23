#version 3.7;
// The three logo objects that the manual lists for logo.inc are declared.
#include "logo.inc"
#ifdef (Povray_Logo) #debug "Povray_Logo\n" #else #debug "missing Povray_Logo\n" #end
#ifdef (Povray_Logo_Prism) #debug "Povray_Logo_Prism\n" #else #debug "missing Povray_Logo_Prism\n" #end
#ifdef (Povray_Logo_Bevel) #debug "Povray_Logo_Bevel\n" #else #debug "missing Povray_Logo_Bevel\n" #end
