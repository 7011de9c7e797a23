#version 3.7;
#declare S = spline {
  natural_spline
  0, <0,0,0>
  1, <1,2,0>
  2, <2,0,0>
}
#for (T, 0, 2, 0.25)
  #debug concat(str(T, 5, 2), ": <", vstr(3, S(T), ", ", 0, 6), ">\n")
#end
