#version 3.7;
#declare S = spline {
  linear_spline
  0, <1, 1>
  1, <2, 2, 2, 2>
}
#for (T, 0, 1, 0.5)
  #debug concat(str(T, 5, 2), ": <", vstr(4, S(T), ", ", 0, 2), ">\n")
#end
