#version 3.7;
#declare S = spline {
  linear_spline
  2, <3, 1, 1>
  0, <0, 0, 0>
  4, <2, 5, 0>
  1, <1, 2, 0>
  3, <4, 4, 2>
}
#for (T, 0, 4, 0.5)
  #debug concat(str(T, 5, 2), ": <", vstr(3, S(T), ", ", 0, 6), ">\n")
#end
