#version 3.7;
#declare S = spline {
  cubic_spline
  0, <0,0,0>
  0.5, <1,0,0>
  2, <1,1,0>
  2.5, <0,1,1>
  5, <0,0,2>
}
#for (T, 0, 5, 0.5)
  #debug concat(str(T, 5, 2), ": <", vstr(3, S(T), ", ", 0, 6), ">\n")
#end
