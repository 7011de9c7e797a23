sphere { <0, 0, 0, 1 pigment { Red } }
sphere { <0, 1,
  1 }
#declare V = <1, , 2>;
