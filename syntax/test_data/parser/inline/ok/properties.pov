object { Thing translate <1, 2, 3> rotate 45*y hollow no_shadow sturm off }
lathe { linear_spline 3, <0, 0>, <1, 1>, <0, 2> }
pigment { checker color Red color Blue scale 0.5 }
