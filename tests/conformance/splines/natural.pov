#version 3.7;
#declare S = spline {
  natural_spline
  0, <0, 0, 0>
  1, <1, 2, 0>
  2, <3, 1, 1>
  3, <4, 4, 2>
  4, <2, 5, 0>
}
#for (T, -0.5, 4.5, 0.5)
  #debug concat(str(T, 5, 2), ": <", vstr(3, S(T), ", ", 0, 6), ">\n")
#end
