#version 3.7;
#declare C = rgb <1, 0.5, 0.2>;
#debug concat("C.gray = ", str(C.gray, 0, 9), "\n")
