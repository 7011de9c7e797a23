#version 3.7;
#macro Foo(Bar, Val) #declare Y = Bar(Val).y; #end
#declare My_Spline = spline { 1, <4,5> 3, <5,5> 5, <6,5> }
Foo(My_Spline, 2)
#debug concat("Y = ", str(Y, 0, 5), "\n")
