#version 3.7;
#debug "before\n"
#declare I = 0;
#while I < 1 #declare I = 1; #end
