#version 3.7;
#declare F = function(a, b) { a + b }
#debug "before\n"
#debug concat("F(1) = ", str(F(1), 0, 0), "\n")
