#version 3.7;
#macro Five() 5 #end
#debug concat("Five() + Five() = ", str(Five() + Five(), 0, 0), "\n")
