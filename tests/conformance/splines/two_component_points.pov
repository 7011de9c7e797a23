#version 3.7;
#declare S = spline {
  linear_spline
  0, <0, 1>
  1, <2, 3>
}
#for (T, 0, 1, 0.25)
  #debug concat(str(T, 5, 2), ": <", vstr(2, S(T), ", ", 0, 6), ">\n")
#end
