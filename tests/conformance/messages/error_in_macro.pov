#version 3.7;
#macro Fail(N)
  #error concat("failed with ", str(N, 0, 0))
#end
#debug "before\n"
Fail(7)
