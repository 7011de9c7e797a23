#declare A = 1;
#local B = <1, 2, 3>
#declare S = sphere { 0, 1 }
#declare T = texture { pigment { Red } };
#declare Arr[2] = 5;
#declare D.key = "value";
#declare deprecated once "use B" Old = 1;
#declare X = #if (A) 1 #else 2 #end;
