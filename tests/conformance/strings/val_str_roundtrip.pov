#version 3.7;
#debug concat("val(str(pi, 0, 5)) = ", str(val(str(pi, 0, 5)), 0, 9), "\n")
