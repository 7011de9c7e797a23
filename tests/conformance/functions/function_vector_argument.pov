#version 3.7;
#declare F = function { x + y + z }
#debug "before\n"
#debug concat("F(<1, 2, 3>) = ", str(F(<1, 2, 3>), 0, 0), "\n")
