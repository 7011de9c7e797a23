#version 3.7;
#declare H = function(h) { h * h + h }
#debug concat("H(3) = ", str(H(3), 0, 6), "\n")
#debug concat("H(-0.5) = ", str(H(-0.5), 0, 6), "\n")
