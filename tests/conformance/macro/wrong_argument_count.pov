#version 3.7;
#macro Two(A, B) (A + B) #end
#debug "before\n"
#debug concat("Two(1) = ", str(Two(1), 0, 0), "\n")
