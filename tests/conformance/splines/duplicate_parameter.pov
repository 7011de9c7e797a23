#version 3.7;
#declare S = spline {
  linear_spline
  0, <0,0,0>
  1, <1,1,1>
  1, <5,5,5>
  2, <2,2,2>
}
#for (T, 0, 2, 0.5)
  #debug concat(str(T, 5, 2), ": <", vstr(3, S(T), ", ", 0, 6), ">\n")
#end
