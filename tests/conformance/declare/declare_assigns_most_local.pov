#version 3.7;
#declare D = 1;
#macro Outer()
  #local D = 10;
  Inner()
  #debug concat("outer sees ", str(D, 0, 0), "\n")
#end
#macro Inner()
  #declare D = D + 1;
#end
Outer()
#debug concat("global ", str(D, 0, 0), "\n")
