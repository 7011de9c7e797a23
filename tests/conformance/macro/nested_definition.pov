#version 3.7;
#macro Maker()
  #macro Made() 123 #end
#end
#ifndef (Made) #debug "not yet\n" #end
Maker()
#debug concat("Made() = ", str(Made(), 0, 0), "\n")
