#version 3.7;
#declare A = function { x + 1 }
#declare B = function { A(x, 0, 0) * 2 }
#declare C = function { B(x, 0, 0) + A(x, 0, 0) }
#debug concat("C(1, 0, 0) = ", str(C(1, 0, 0), 0, 3), "\n")
