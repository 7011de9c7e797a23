#version 3.7;
#declare Times = 0;
#for (I, 1, 3)
  #include "include_counter.inc"
#end
#debug concat("Times = ", str(Times, 0, 0), "\n")
