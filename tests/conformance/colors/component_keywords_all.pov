#version 3.7;
#declare C = color blue 0.3 transmit 0.9 filter 0.1 red 0.2 green 0.4;
#debug concat("C = <", vstr(5, C, ", ", 0, 2), ">\n")
