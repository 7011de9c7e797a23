#version 3.7;
#macro Hello()
  #debug "hello from macro\n"
#end
Hello()
Hello()
