#version 3.7;
#declare Arr = array[3];
#declare Arr[1] = 7;
#ifdef (Arr[0]) #debug "0 set\n" #else #debug "0 unset\n" #end
#ifdef (Arr[1]) #debug "1 set\n" #else #debug "1 unset\n" #end
