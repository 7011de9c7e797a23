// Macro calls wherever a value or an item may stand.
#macro Pos(I) <I, 0, 0> #end
#macro Rad() 0.5 #end
#macro Paint(C) pigment { color C } #end
#macro Spheres(N)
  #local I = 0;
  #while (I < N)
    sphere { Pos(I), Rad() Paint(rgb I/N) }
    #local I = I + 1;
  #end
#end
union { Spheres(5) translate -2*x }
#declare Center = Pos(Rad()*2) + <0, Rad(), 0>;
sphere_sweep { linear_spline 2, Pos(0), Rad(), Pos(1), Rad() }
