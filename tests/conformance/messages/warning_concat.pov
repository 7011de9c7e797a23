#version 3.7;
#warning concat("value ", str(3, 0, 1))
#debug "after warning\n"
