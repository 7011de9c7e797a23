#version 3.7;
#debug "before\n"
#for (I, 1, 2, 0) #break #end
#debug "after\n"
