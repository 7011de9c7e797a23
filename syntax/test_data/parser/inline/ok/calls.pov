Row(1, sphere { 0, 1 }, pigment { Red })
Field(HF, off, off <100, 100>, on)
#declare V = vrotate(x, <0, 90, 0>);
#declare P = S(0.5, natural_spline);
