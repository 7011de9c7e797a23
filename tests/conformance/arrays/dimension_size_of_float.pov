#version 3.7;
#declare F = 3;
#debug "before\n"
#debug concat("dimension_size(F, 1) = ", str(dimension_size(F, 1), 0, 0), "\n")
