#declare V = <1, -2, 3*4> + <A, B> * <1, 2, 3, 4, 5>;
#declare W = <1 0 -1>;
sphere_sweep { b_spline 2, #while (I < 2) <I, 0, 0>, 1 #local I = I + 1; #end }
