#version 3.7;
#debug "one "
#debug "two "
#debug "three\n"
