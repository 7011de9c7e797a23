#version 3.7;
#macro M()
  #declare Fresh = 42;
#end
M()
#debug concat("Fresh = ", str(Fresh, 0, 0), "\n")
