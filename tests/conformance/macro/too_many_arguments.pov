#version 3.7;
#macro One(A) (A) #end
#debug "before\n"
#debug concat("One(1, 2) = ", str(One(1, 2), 0, 0), "\n")
