#version 3.7;
#local A = 5;
#macro Get() A #end
#debug concat("Get() = ", str(Get(), 0, 0), "\n")
