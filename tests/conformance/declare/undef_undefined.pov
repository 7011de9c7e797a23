#version 3.7;
#undef Never
#debug "still running\n"
