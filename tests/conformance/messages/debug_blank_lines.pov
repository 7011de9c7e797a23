#version 3.7;
#debug "\n\n"
#debug "after blanks\n"
