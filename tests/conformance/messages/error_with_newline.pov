#version 3.7;
#error "stop\n"
