#version 3.7;
#macro Foo(Bar, X)
  #declare Y = Bar(X);
  #declare Z = Bar(Y);
#end
#declare FUNC = function(n) { n + 2 }
Foo(FUNC, 1)
#debug concat("Y = ", str(Y, 0, 5), "\n")
#debug concat("Z = ", str(Z, 0, 5), "\n")
