#version 3.7;
#declare C = rgb <0.1, 0.2, 0.3>;
#declare D = C * 3;
#debug concat("D.red = ", str(D.red, 0, 12), "\n")
#debug concat("(C.red * 3) = ", str((C.red * 3), 0, 12), "\n")
