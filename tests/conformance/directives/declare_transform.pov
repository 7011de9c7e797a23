#version 3.7;
#declare T = transform { rotate 90*z translate x }
#debug "transform declared\n"
