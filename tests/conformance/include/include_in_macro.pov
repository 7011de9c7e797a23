#version 3.7;
#macro Load()
  #include "include_locals.inc"
  #debug concat("in macro: ", str(defined(Include_Local), 0, 0), "\n")
#end
Load()
#debug concat("after macro: ", str(defined(Include_Local), 0, 0), "\n")
