#version 3.7;
#if (0)
  #while (1) #end
  #if (1) #error "never" #end
#end
#debug "ok\n"
