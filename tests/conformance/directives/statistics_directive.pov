#version 3.7;
#debug "before\n"
#statistics "stats text\n"
#debug "after\n"
