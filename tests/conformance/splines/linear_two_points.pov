#version 3.7;
#declare S = spline {
  linear_spline
  0, <0,0,0>
  10, <10,20,30>
}
#for (T, -1, 11, 2)
  #debug concat(str(T, 5, 2), ": <", vstr(3, S(T), ", ", 0, 6), ">\n")
#end
