#version 3.7;
#declare S = spline {
  linear_spline
  0, <0, 1, 2, 3, 4>
  1, <4, 3, 2, 1, 0>
}
#for (T, 0, 1, 0.5)
  #debug concat(str(T, 5, 2), ": <", vstr(5, S(T), ", ", 0, 2), ">\n")
#end
