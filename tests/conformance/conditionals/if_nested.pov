#version 3.7;
#declare A = 1;
#declare B = 0;
#if (A)
  #if (B) #debug "A and B\n" #else #debug "A not B\n" #end
#else
  #debug "not A\n"
#end
