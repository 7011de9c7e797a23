#version 3.7;
#debug "before\n"
#fopen F "missing.txt" read
