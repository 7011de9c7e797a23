#version 3.7;
#declare D = 1;
#macro M()
  #local D = D + 1;
  #debug concat(str(D, 0, 0), "\n")
#end
#debug "before\n"
M()
