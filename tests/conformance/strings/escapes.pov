#version 3.7;
#debug "tab:[\t] backslash:[\\] quote:[\"] apostrophe:[\']\n"
