#version 3.7;
#declare A = "left";
#declare B = "right";
#debug concat("concat(A, \"-\", B) = [", concat(A, "-", B), "]\n")
