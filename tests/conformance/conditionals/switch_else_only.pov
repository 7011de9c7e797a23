#version 3.7;
#switch (3)
  #else #debug "only else\n"
#end
