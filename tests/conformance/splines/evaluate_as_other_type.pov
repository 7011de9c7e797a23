#version 3.7;
#declare S = spline { linear_spline
  0, <0, 0, 0>
  1, <1, 2, 0>
  2, <3, 1, 1>
  3, <4, 4, 2>
  4, <2, 5, 0>
}
#for (T, 0.5, 3.5, 1)
  #debug concat(str(T, 0, 1), " cubic: <", vstr(3, S(T, cubic_spline), ",", 0, 4), ">\n")
  #debug concat(str(T, 0, 1), " natural: <", vstr(3, S(T, natural_spline), ",", 0, 4), ">\n")
  #debug concat(str(T, 0, 1), " quadratic: <", vstr(3, S(T, quadratic_spline), ",", 0, 4), ">\n")
#end
