#version 3.7;
#debug "before\n"
#error concat("bad value ", str(42, 0, 0))
