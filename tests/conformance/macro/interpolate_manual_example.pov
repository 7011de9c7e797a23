#version 3.7;
#macro Interpolate(T, T1, T2, P1, P2)
  (P1 + (T1 + T / (T2 - T1)) * (P2 - P1))
#end
#debug concat("Interpolate(5, 0, 15, 3.0, 5.5) = ", str(Interpolate(5, 0, 15, 3.0, 5.5), 0, 6), "\n")
#debug concat("Interpolate(5, 0, 15, <2,3,4>, <9,8,7>) = <", vstr(3, Interpolate(5, 0, 15, <2,3,4>, <9,8,7>), ", ", 0, 6), ">\n")
