#version 3.7;
#declare F = function(a) { a }
#debug "before\n"
#debug concat("F(1, 2) = ", str(F(1, 2), 0, 0), "\n")
