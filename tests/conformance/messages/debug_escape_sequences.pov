#version 3.7;
#debug "a\tb\\c\"d\n"
