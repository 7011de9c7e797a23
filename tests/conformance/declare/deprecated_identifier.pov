#version 3.7;
#declare deprecated Old = 5;
#debug "declared\n"
#debug concat("Old = ", str(Old, 0, 0), "\n")
